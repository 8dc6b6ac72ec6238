package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** ArActionLimiterRot.cpp's rules: a reading within the robot's radius, either side, limits rotation. */
class ArActionLimiterRotTest {
    private final ActionFixture f = new ActionFixture();
    private final ArActionLimiterRot limiter = f.attach(new ArActionLimiterRot());
    private final ArRangeDevice device = new ArRangeDevice("test", 5000);
    private double radius;

    @BeforeEach
    void attachADevice() {
        f.robot.addRangeDevice(device);
        f.at(0, 0, 0, 0);
        radius = f.robot.getRobotRadius();
    }

    @Test
    void byDefaultItDoesNotCheckTheRadius() {
        device.addReading(0, radius - 50);
        assertNull(ActionFixture.fire(limiter));
    }

    @Test
    void aReadingWithinTheRadiusOnTheLeftAllowsNoRotation() {
        limiter.setParameters(true);
        device.addReading(0, radius - 50);
        ArActionDesired d = ActionFixture.fire(limiter);
        assertEquals(0, d.getMaxRotVel());
        assertEquals(1, d.getMaxRotVelStrength());
    }

    @Test
    void aReadingWithinTheRadiusOnTheRightAllowsTheInRadiusSpeed() {
        limiter.setParameters(true, 20);
        device.addReading(-10, -(radius - 30));
        assertEquals(20, ActionFixture.fire(limiter).getMaxRotVel());
    }

    @Test
    void aReadingBeyondTheRadiusOrNoneAsksForNothing() {
        limiter.setParameters(true, 20);
        assertNull(ActionFixture.fire(limiter));
        device.addReading(radius + 100, 0);
        assertNull(ActionFixture.fire(limiter));
    }

    @Test
    void withoutARangeDeviceItAsksForNothing() {
        ActionFixture g = new ActionFixture();
        ArActionLimiterRot l = g.attach(new ArActionLimiterRot("l"));
        l.setParameters(true);
        g.at(0, 0, 0, 0);
        assertNull(ActionFixture.fire(l));
    }
}
