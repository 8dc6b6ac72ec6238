package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * ArRobot's methods are declared in package-private layers; as seen from outside the package they
 * must stay ArRobot's own: reachable by reflection, with the generic types they are declared with.
 */
class ArRobotLayersTest {
    @Test
    void everyPublicMethodIsReachableThroughAPublicClass() {
        List<String> hidden = new ArrayList<>();
        for (Method m : ArRobot.class.getMethods()) {
            if (!Modifier.isPublic(m.getDeclaringClass().getModifiers())) {
                hidden.add(m.getName() + Arrays.toString(m.getParameterTypes()));
            }
        }
        assertEquals(List.of(), hidden, "a final method in a layer gets no public bridge in ArRobot");
    }

    @Test
    void everyPublicMethodShowsTheGenericTypesItIsDeclaredWith() {
        List<String> raw = new ArrayList<>();
        for (Method m : ArRobot.class.getMethods()) {
            Method declared = declaration(m);
            if (!declared.toGenericString().equals(m.toGenericString()
                    .replace(m.getDeclaringClass().getName() + ".", declared.getDeclaringClass().getName() + "."))) {
                raw.add(m.toGenericString());
            }
        }
        assertEquals(List.of(), raw, "a bridge to a layer's generic method carries raw types: declare it in ArRobot");
    }

    @Test
    void theLayersArePackagePrivateAndAbstract() {
        for (Class<?> c = ArRobot.class.getSuperclass(); c.getPackage() == ArRobot.class.getPackage();
                c = c.getSuperclass()) {
            assertTrue(Modifier.isAbstract(c.getModifiers()) && !Modifier.isPublic(c.getModifiers()), c.getName());
        }
    }

    /** @return the method itself, or the one it bridges to: the first non-bridge declaration up the chain */
    private static Method declaration(Method m) {
        if (!m.isBridge()) {
            return m;
        }
        for (Class<?> c = m.getDeclaringClass().getSuperclass(); c != null; c = c.getSuperclass()) {
            try {
                Method d = c.getDeclaredMethod(m.getName(), m.getParameterTypes());
                if (!d.isBridge()) {
                    return d;
                }
            } catch (NoSuchMethodException e) {
                // declared higher up
            }
        }
        throw new AssertionError("no declaration of " + m);
    }
}
