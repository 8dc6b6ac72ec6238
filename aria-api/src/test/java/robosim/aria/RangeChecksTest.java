package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** ARIA's checkRangeDevicesCurrentBox and Polar over all of a robot's devices (ArRobot.cpp, ArRangeBuffer.cpp). */
class RangeChecksTest {
    private final ActionFixture f = new ActionFixture();

    @Test
    void withoutRangeDevicesBothAnswerMinusOne() {
        f.at(0, 0, 0, 0);
        assertEquals(-1, RangeChecks.currentBox(f.robot, 0, -500, 2000, 500, null));
        assertEquals(-1, RangeChecks.currentPolar(f.robot, -90, 90, null));
    }

    @Test
    void theClosestReadingOfAnyDeviceWinsAndADeviceWithNothingAnswersItsMaximumRange() {
        ArRangeDevice near = new ArRangeDevice("near", 5000);
        ArRangeDevice empty = new ArRangeDevice("empty", 3000);
        f.robot.addRangeDevice(near);
        f.robot.addRangeDevice(empty);
        f.at(1000, 1000, 90, 0);
        assertEquals(3000, RangeChecks.currentBox(f.robot, 0, -500, 2000, 500, null), "the empty device's range");
        near.addReading(1100, 2200);
        ArPose at = new ArPose();
        // 1200 ahead and 100 to the right of a robot facing +y
        assertEquals(Math.hypot(1200, 100), RangeChecks.currentBox(f.robot, 2000, 500, 0, -500, at), 1e-9);
        assertEquals(1200, at.getX(), 1e-9);
        assertEquals(-100, at.getY(), 1e-9);
        double[] angle = new double[1];
        assertEquals(Math.hypot(1200, 100), RangeChecks.currentPolar(f.robot, -90, 90, angle), 1e-9);
        assertEquals(Math.toDegrees(Math.atan2(-100, 1200)), angle[0], 1e-6);
    }

    @Test
    void aReadingOnTheBoxsEdgeCountsAndOneBeyondItDoesNot() {
        ArRangeDevice d = new ArRangeDevice("d", 5000);
        f.robot.addRangeDevice(d);
        f.at(0, 0, 0, 0);
        d.addReading(1000, 500);
        assertEquals(Math.hypot(1000, 500), RangeChecks.currentBox(f.robot, 0, -500, 2000, 500, null), 1e-9);
        assertEquals(5000, RangeChecks.currentBox(f.robot, 0, -499, 2000, 499, null));
    }
}
