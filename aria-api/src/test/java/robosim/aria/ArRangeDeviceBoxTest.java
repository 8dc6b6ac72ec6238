package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * currentReadingBox / cumulativeReadingBox (ARIA's ArRangeBuffer::getClosestBox): the box is in the
 * robot's frame, its corners in any order, edges included; the answer is the distance from the robot
 * centre. The robot stands at (1000, 500) facing +y (90°).
 */
class ArRangeDeviceBoxTest {
    private ArRobot robot;
    private ArRangeDevice device;

    @BeforeEach
    void robotFacingPlusY() {
        robot = Cycles.p3dxRobot();
        device = new ArRangeDevice("test", 5000, 10, 10);
        robot.addRangeDevice(device);
        Cycles.cycle(robot, 100, 1000, 500, 90);
        // 600 ahead, 200 to the left: robot frame (600, 200)
        device.addReading(800, 1100);
        // 300 ahead, 400 to the right: robot frame (300, -400)
        device.addReading(1400, 800);
    }

    @Test
    void theNearestReadingInTheBoxIsMeasuredFromTheRobotCentre() {
        assertEquals(Math.hypot(600, 200), device.currentReadingBox(0, 0, 1000, 300), 1e-9);
        assertEquals(Math.hypot(600, 200), device.cumulativeReadingBox(0, 0, 1000, 300), 1e-9);
    }

    @Test
    void cornersMayComeInAnyOrder() {
        assertEquals(500, device.currentReadingBox(1000, 300, 0, -500), 1e-9);
    }

    @Test
    void theEdgesAreInside() {
        assertEquals(500, device.currentReadingBox(300, -400, 400, 0), 1e-9);
    }

    @Test
    void anEmptyBoxAnswersTheMaximumRangeAndTheOrigin() {
        ArPose at = new ArPose(1, 2, 3);
        assertEquals(5000, device.currentReadingBox(-1000, -1000, -10, 1000, at));
        assertEquals(0, at.getX());
        assertEquals(0, at.getY());
        assertEquals(0, at.getTh());
    }

    @Test
    void theReadingIsGivenInTheRobotsFrame() {
        ArPose at = new ArPose();
        device.currentReadingBox(0, -1000, 1000, 1000, at);
        assertEquals(300, at.getX(), 1e-9);
        assertEquals(-400, at.getY(), 1e-9);
    }

    @Test
    void theAnswerIsCappedAtTheMaximumRange() {
        device.setMaxRange(450);
        assertEquals(450, device.currentReadingBox(0, -1000, 1000, 1000), 1e-9);
    }
}
