package robosim.scout;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.scout.StateVector.STATE_CONF_STEER;
import static robosim.scout.StateVector.STATE_CONF_X;
import static robosim.scout.StateVector.STATE_CONF_Y;

import org.junit.jupiter.api.Test;

/** zr, dp and da redefine the frame the configuration is reported in; the robot goes on from there. */
class PoseFrameTest {
    private final ScriptedScout scout = new ScriptedScout();

    /** A state at a pose, 254 mm (100 tenths of an inch) along the heading from (x, y). */
    private void queueAhead(long step, double x, double y, double th) {
        double a = Math.toRadians(th);
        scout.queue(ScriptedScout.at(step, x + 254 * Math.cos(a), y + 254 * Math.sin(a), th, 0, 0, new int[0], 0));
    }

    private long[] conf() {
        assertTrue(scout.get_rc());
        return new long[] {scout.State[STATE_CONF_X], scout.State[STATE_CONF_Y], scout.State[STATE_CONF_STEER]};
    }

    @Test
    void zrMakesTheCurrentPoseTheOrigin() {
        scout.deliver(ScriptedScout.at(1, 1000, 500, 30, 0, 0, new int[0], 0));
        assertTrue(scout.zr());
        queueAhead(2, 1000, 500, 30);
        assertEquals(100, conf()[0], "100 tenths of an inch ahead");
        assertEquals(0, scout.State[STATE_CONF_Y]);
        assertEquals(0, scout.State[STATE_CONF_STEER]);
    }

    @Test
    void zrThenATurnReadsTheTurn() {
        scout.deliver(ScriptedScout.at(1, 1000, 500, 170, 0, 0, new int[0], 0));
        assertTrue(scout.zr());
        scout.queue(ScriptedScout.at(2, 1000, 500, -170, 0, 0, new int[0], 0));
        assertEquals(200, conf()[2], "20 degrees counter-clockwise, through 180");
        scout.queue(ScriptedScout.at(3, 1000, 500, 150, 0, 0, new int[0], 0));
        assertEquals(3400, conf()[2], "20 degrees clockwise");
    }

    @Test
    void dpDefinesThePositionAndKeepsTheHeading() {
        scout.deliver(ScriptedScout.at(1, 1000, 500, 90, 0, 0, new int[0], 0));
        assertTrue(scout.dp(100, 200));
        queueAhead(2, 1000, 500, 90);
        assertEquals(100, conf()[0]);
        assertEquals(300, scout.State[STATE_CONF_Y], "100 more along the heading, +y");
        assertEquals(900, scout.State[STATE_CONF_STEER]);
    }

    @Test
    void daDefinesTheHeadingAndKeepsThePosition() {
        scout.deliver(ScriptedScout.at(1, 1000, 500, 0, 0, 0, new int[0], 0));
        assertTrue(scout.dp(0, 0));
        assertTrue(scout.da(900, 0));
        queueAhead(2, 1000, 500, 0);
        long[] c = conf();
        assertEquals(0, c[0]);
        assertEquals(100, c[1], "driving along the old x axis is now along +y");
        assertEquals(900, c[2]);
    }

    @Test
    void theFrameLastsUntilRedefined() {
        scout.deliver(ScriptedScout.at(1, 254, 254, 45, 0, 0, new int[0], 0));
        assertTrue(scout.zr());
        assertTrue(scout.dp(-50, 70));
        queueAhead(2, 254, 254, 45);
        long[] c = conf();
        assertEquals(50, c[0]);
        assertEquals(70, c[1]);
        assertEquals(0, c[2]);
        scout.queue(ScriptedScout.at(3, 254, 254, 45, 0, 0, new int[0], 0));
        assertEquals(-50, conf()[0], "back where dp was called");
    }
}
