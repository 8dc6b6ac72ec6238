package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

/**
 * ArActionJoydrive.cpp and ArJoyHandler: no joystick in the simulation, so it wants nothing; with a
 * joystick (a test double) ARIA's rules.
 */
class ArActionJoydriveTest {
    /** A joystick held at a position. */
    private static final class Held extends ArJoyHandler {
        double x;
        double y;
        boolean button;

        @Override
        public synchronized boolean haveJoystick() {
            return true;
        }

        @Override
        public boolean getButton(int b) {
            return b == 1 && button;
        }

        @Override
        public void getDoubles(double[] x, double[] y, double[] z) {
            x[0] = this.x;
            y[0] = this.y;
        }
    }

    @Test
    void theSimulatorsJoyHandlerFindsNoJoystick() {
        ArJoyHandler joy = new ArJoyHandler();
        assertFalse(joy.init());
        assertFalse(joy.haveJoystick());
        assertFalse(joy.getButton(1));
        assertEquals(0, joy.getNumButtons());
        assertEquals(0, joy.getNumAxes());
        double[] x = {5};
        double[] y = {5};
        joy.getDoubles(x, y);
        assertEquals(0, x[0]);
        assertEquals(0, y[0]);
    }

    @Test
    void theJoyHandlerKeepsItsSpeedsAndCalibration() {
        ArJoyHandler joy = new ArJoyHandler(false);
        assertFalse(joy.getUseOSCal());
        joy.setSpeeds(100, 200, 3);
        int[] a = new int[1];
        int[] b = new int[1];
        int[] c = new int[1];
        joy.getSpeeds(a, b, c);
        assertEquals(100, a[0]);
        assertEquals(200, b[0]);
        assertEquals(3, c[0]);
        joy.setStats(10, -10, 20, -20, 1, 2);
        int[] cenY = new int[1];
        joy.getStats(null, null, null, null, null, cenY);
        assertEquals(2, cenY[0]);
    }

    @Test
    void withoutAJoystickItWantsNothingEvenIfItShouldStop() {
        ArActionJoydrive joydrive = new ArActionJoydrive();
        assertFalse(joydrive.joystickInited());
        assertNull(ActionFixture.fire(joydrive));
        assertEquals(4, joydrive.getNumArgs());
    }

    @Test
    void withTheButtonHeldTheStickGivesVelocityAndTheOppositeDeltaHeading() {
        Held held = new Held();
        ArActionJoydrive joydrive = new ArActionJoydrive("j", 400, 15, true, true, held);
        held.button = true;
        held.x = 0.5;
        held.y = -0.25;
        ArActionDesired d = ActionFixture.fire(joydrive);
        assertEquals(-100, d.getVel());
        assertEquals(-7.5, d.getDeltaHeading());
    }

    @Test
    void withAJoystickAndNoButtonItStopsOnlyIfAskedTo() {
        Held held = new Held();
        ArActionJoydrive joydrive = new ArActionJoydrive("j", 400, 15, true, true, held);
        ArActionDesired d = ActionFixture.fire(joydrive);
        assertEquals(0, d.getVel());
        assertEquals(1, d.getVelStrength());
        joydrive.setStopIfNoButtonPressed(false);
        assertNull(ActionFixture.fire(joydrive));
    }
}
