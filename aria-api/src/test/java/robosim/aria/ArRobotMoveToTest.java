package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * moveTo re-bases the odometric pose as ARIA's ArRobot::moveTo does: getPose answers the new pose and
 * follows the encoders from there, getEncoderPose keeps the raw pose, and the readings of range
 * devices and sonars move with the robot.
 */
class ArRobotMoveToTest {
    private ArRobot robot;
    private ArRangeDevice device;

    @BeforeEach
    void robotAt1000And0() {
        robot = Cycles.p3dxRobot();
        device = new ArRangeDevice("test", 5000, 10, 10);
        robot.addRangeDevice(device);
        Cycles.cycle(robot, 100, 1000, 0, 0);
    }

    private static void assertPose(double x, double y, double th, ArPose p) {
        assertEquals(x, p.getX(), 1e-9, "x");
        assertEquals(y, p.getY(), 1e-9, "y");
        assertEquals(th, p.getTh(), 1e-9, "th");
    }

    @Test
    void getPoseAnswersTheNewPoseAndTheEncoderPoseStays() {
        robot.moveTo(new ArPose(5000, 5000, 90));
        assertPose(5000, 5000, 90, robot.getPose());
        assertPose(1000, 0, 0, robot.getEncoderPose());
        assertEquals(5000, robot.getX(), 1e-9);
        assertEquals(90, robot.getTh(), 1e-9);
    }

    @Test
    void theEncodersMotionIsAddedInTheNewFrame() {
        robot.moveTo(new ArPose(5000, 5000, 90));
        // 100 mm forward along the encoders' x is 100 mm along +y in the new frame
        Cycles.cycle(robot, 200, 1100, 0, 0);
        assertPose(5000, 5100, 90, robot.getPose());
    }

    @Test
    void bufferedReadingsKeepTheirPlaceRelativeToTheRobot() {
        device.addReading(1500, 0);
        robot.moveTo(new ArPose(5000, 5000, 90));
        List<ArPose> current = device.getCurrentBuffer();
        assertPose(5000, 5500, 0, current.get(0));
        assertPose(5000, 5500, 0, device.getCumulativeBuffer().get(0));
        assertEquals(500, device.currentReadingPolar(-10, 10), 1e-9);
    }

    @Test
    void withoutDoCumulativeTheCumulativeBufferStays() {
        device.addReading(1500, 0);
        robot.moveTo(new ArPose(1000, 100, 0), false);
        assertPose(1500, 100, 0, device.getCurrentBuffer().get(0));
        assertPose(1500, 0, 0, device.getCumulativeBuffer().get(0));
    }

    @Test
    void sonarReadingsMoveWithTheRobot() {
        int[] sonar = new int[16];
        java.util.Arrays.fill(sonar, 1000);
        Cycles.cycle(robot, 200, 1000, 0, 0, sonar, new int[0]);
        ArSensorReading ahead = robot.getSonarReading(3);
        double dx = ahead.getX() - 1000;
        double dy = ahead.getY();
        robot.moveTo(new ArPose(0, 0, 180));
        assertEquals(-dx, ahead.getX(), 1e-9);
        assertEquals(-dy, ahead.getY(), 1e-9);
    }

    @Test
    void moveToFromShiftsTheFrameByTheDifference() {
        robot.moveTo(new ArPose(2000, 0, 0));
        // the robot was at (2000, 0) in the current frame; that place is (2500, 100) in the new one
        robot.moveTo(new ArPose(2500, 100, 0), new ArPose(2000, 0, 0));
        assertPose(2500, 100, 0, robot.getPose());
        assertPose(1000, 0, 0, robot.getEncoderPose());
    }

    @Test
    void aTurnedFrameKeepsTheEncodersHeadingApart() {
        robot.moveTo(new ArPose(0, 0, 170));
        Cycles.cycle(robot, 200, 1000, 0, 20);
        assertEquals(-170, robot.getTh(), 1e-9);
        assertEquals(20, robot.getEncoderPose().getTh(), 1e-9);
    }
}
