package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** An action's parameters (ARIA's ArArg and setNextArgument): found, read and set by others. */
@Timeout(value = 10, unit = TimeUnit.SECONDS)
class ArArgTest {
    static final class Go extends ArAction {
        double maxSpeed = 500;
        int tries = 3;

        Go() {
            super("Go", "Drives forward.");
            setNextArgument(ArArg.ofDouble("maximum speed", () -> maxSpeed, v -> maxSpeed = v, "Maximum speed to go."));
            setNextArgument(ArArg.ofInt("tries", () -> tries, v -> tries = v, ""));
        }

        @Override
        public ArActionDesired fire(ArActionDesired current) {
            return null;
        }
    }

    @Test
    void anActionsParametersAreFoundReadAndSetThroughItsArgs() {
        Go go = new Go();
        assertEquals(2, go.getNumArgs());
        ArArg speed = go.getArg(0);
        assertEquals("maximum speed", speed.getName());
        assertEquals(ArArg.Type.DOUBLE, speed.getType());
        assertEquals(500, speed.getDouble());
        assertTrue(speed.setDouble(250));
        assertEquals(250, go.maxSpeed, "setting the argument sets the action's value");
        go.getArg(1).setInt(5);
        assertEquals(5, go.tries);
        assertNull(go.getArg(2));
        assertThrows(IllegalStateException.class, () -> go.getArg(1).getDouble(), "an int is not a double");
        ByteArrayOutputStream log = new ByteArrayOutputStream();
        ArLog.setStream(new PrintStream(log, true, StandardCharsets.UTF_8));
        try {
            go.log();
        } finally {
            ArLog.setStream(null);
        }
        String out = log.toString(StandardCharsets.UTF_8);
        assertTrue(out.startsWith("Action Go isActive true\nAction description:\nDrives forward.\nParameters:\n"
                + "Parameter #0:\n\tName: maximum speed\n\tType: double: 250.000\n"), out);
    }
}
