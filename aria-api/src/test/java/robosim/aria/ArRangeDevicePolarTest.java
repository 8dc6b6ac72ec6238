package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * currentReadingPolar / cumulativeReadingPolar: the nearest reading whose direction, relative to the
 * robot's heading, lies strictly inside ARIA's wrapping interval. The robot stands at (1000, 500)
 * facing +y (90°).
 */
class ArRangeDevicePolarTest {
    private ArRobot robot;
    private ArRangeDevice device;

    @BeforeEach
    void robotFacingPlusY() {
        robot = Cycles.p3dxRobot();
        device = new ArRangeDevice("test", 5000, 10, 10);
        robot.addRangeDevice(device);
        Cycles.cycle(robot, 100, 1000, 500, 90);
    }

    /** 800 mm straight behind the robot: relative angle 180°. */
    private void readingBehind() {
        device.addReading(1000, -300);
    }

    /** 1000 mm at 45° to the robot's left, and 600 mm at 30° to its right. */
    private void readingsInFront() {
        device.addReading(1000 - 707.10678118654755, 500 + 707.10678118654755);
        device.addReading(1300, 500 + 519.61524227066319);
    }

    @Test
    void aReadingBehindIsFoundThroughTheBack() {
        readingBehind();
        assertEquals(800, device.currentReadingPolar(170, -170), 1e-6);
        assertEquals(800, device.cumulativeReadingPolar(170, -170), 1e-6);
    }

    @Test
    void aReadingBehindIsNotInTheFrontInterval() {
        readingBehind();
        assertEquals(5000, device.currentReadingPolar(-170, 170));
        assertEquals(5000, device.cumulativeReadingPolar(-170, 170));
    }

    @Test
    void boundsAreNormalised() {
        readingBehind();
        assertEquals(800, device.currentReadingPolar(530, 190), 1e-6);
    }

    @Test
    void equalBoundsMatchNothing() {
        readingBehind();
        readingsInFront();
        assertEquals(5000, device.currentReadingPolar(45, 45));
        assertEquals(5000, device.currentReadingPolar(180, -180), "both normalise to 180");
        assertEquals(5000, device.cumulativeReadingPolar(-30, -30));
    }

    @Test
    void theNearestReadingInsideWins() {
        readingBehind();
        readingsInFront();
        assertEquals(600, device.currentReadingPolar(-90, 90), 1e-6);
        assertEquals(1000, device.currentReadingPolar(0, 90), 1e-6);
    }

    @Test
    void angleOutReceivesTheReadingsRelativeAngle() {
        readingBehind();
        readingsInFront();
        double[] angle = {Double.NaN};
        assertEquals(1000, device.currentReadingPolar(0, 90, angle), 1e-6);
        assertEquals(45, angle[0], 1e-6);
        assertEquals(600, device.cumulativeReadingPolar(-90, 90, angle), 1e-6);
        assertEquals(-30, angle[0], 1e-6);
        assertEquals(800, device.currentReadingPolar(170, -170, angle), 1e-6);
        assertEquals(180, angle[0], 1e-6);
    }

    @Test
    void angleOutIsLeftAsItWasWhenNothingIsFound() {
        double[] angle = {Double.NaN};
        assertEquals(5000, device.currentReadingPolar(-10, 10, angle));
        assertTrue(Double.isNaN(angle[0]));
    }

    @Test
    void anEmptyAngleOutIsRejected() {
        assertThrows(IllegalArgumentException.class, () -> device.currentReadingPolar(-10, 10, new double[0]));
    }

    @Test
    void aReadingOnABoundIsOutside() {
        Cycles.cycle(robot, 200, 0, 0, 0);
        device.addReading(500, 0);
        assertEquals(5000, device.currentReadingPolar(0, 20));
        assertEquals(500, device.currentReadingPolar(-1, 20), 1e-9);
    }

    @Test
    void theAnswerIsAtMostTheMaximumRange() {
        device.addReading(1000, 500 + 6000);
        assertEquals(5000, device.currentReadingPolar(-10, 10));
    }

    @Test
    void theCumulativeQueryAnswersAfterTheCurrentReadingsExpired() {
        readingBehind();
        Cycles.cycle(robot, 5200, 1000, 500, 90);
        assertEquals(5000, device.currentReadingPolar(170, -170));
        assertEquals(800, device.cumulativeReadingPolar(170, -170), 1e-6);
    }

    @Test
    void distancesAreFromTheRobotsCurrentPose() {
        readingBehind();
        Cycles.cycle(robot, 200, 1000, 0, -90);
        assertEquals(300, device.currentReadingPolar(-10, 10), 1e-6, "after turning round, it is ahead");
    }
}
