package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** {@code robosim panel}'s command line, refused before any window opens (the window itself is tested in the integration tests). */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class PanelCommandTest {
    @TempDir
    Path dir;

    @Test
    void aPortOutOfRangeIsRefused() {
        Run run = Run.execute("panel", "--attach", "--viewer-port", "70000");

        assertEquals(2, run.exit());
        assertEquals("robosim panel: --viewer-port: a port from 1 to 65535, got 70000", run.firstLine());
    }

    @Test
    void aWorldThatIsNotThereIsNamed() {
        Path missing = dir.resolve("none.xml");
        Run run = Run.execute("panel", missing.toString());

        assertEquals(2, run.exit());
        assertEquals("robosim panel: WORLD: no such file: " + missing, run.firstLine());
    }

    @Test
    void startWithoutAWorldIsRefused() {
        Run run = Run.execute("panel", "--start");

        assertEquals(2, run.exit());
        assertEquals("robosim panel: --start: give the WORLD to start", run.firstLine());
    }

    @Test
    void aSecretFileThatBreaksTheRuleIsRefusedWithoutRepeatingIt() throws Exception {
        Path secret = Files.writeString(dir.resolve("secret"), "short");
        Run run = Run.execute("panel", "--attach", "--secret-file", secret.toString());

        assertEquals(2, run.exit());
        assertEquals("robosim panel: --secret-file: " + secret + ": the run secret given (5 characters) breaks the"
                + " rule: a run secret is 16 to 128 letters, digits, '-' or '_'", run.firstLine());
    }
}
