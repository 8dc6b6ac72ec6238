package robosim.it;

import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.BeforeEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;
import robosim.protocol.RunSecret;

/**
 * Runs a test without the system property {@value RunSecret#PROPERTY}, and puts it back after:
 * the command lines and the ControlPanel that other tests run in this JVM set it (as they do in a
 * JVM of their own, which then ends), and a client finds it before any secret file.
 */
final class NoSecretProperty implements BeforeEachCallback, AfterEachCallback {
    private static final ExtensionContext.Namespace HERE = ExtensionContext.Namespace.create(NoSecretProperty.class);

    @Override
    public void beforeEach(ExtensionContext context) {
        String before = System.getProperty(RunSecret.PROPERTY);
        if (before != null) {
            context.getStore(HERE).put(RunSecret.PROPERTY, before);
        }
        System.clearProperty(RunSecret.PROPERTY);
    }

    @Override
    public void afterEach(ExtensionContext context) {
        String before = context.getStore(HERE).remove(RunSecret.PROPERTY, String.class);
        if (before == null) {
            System.clearProperty(RunSecret.PROPERTY);
        } else {
            System.setProperty(RunSecret.PROPERTY, before);
        }
    }
}
