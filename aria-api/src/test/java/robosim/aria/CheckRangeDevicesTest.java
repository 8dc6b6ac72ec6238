package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * ArRobot's checkRangeDevices* (ARIA's ArRobot.cpp): the smallest answer of the attached devices, −1
 * with none attached; a device with nothing in the region counts with its maximum range. The robot
 * stands at the origin facing +x.
 */
class CheckRangeDevicesTest {
    private ArRobot robot;
    private ArRangeDevice near;
    private ArRangeDevice far;

    @BeforeEach
    void twoDevices() {
        robot = Cycles.p3dxRobot();
        Cycles.cycle(robot, 100, 0, 0, 0);
        far = new ArRangeDevice("far", 4000, 10, 10);
        near = new ArRangeDevice("near", 3000, 10, 10);
        robot.addRangeDevice(far);
        robot.addRangeDevice(near);
        far.addReading(2000, 0);
        near.addReading(800, 800);
    }

    @Test
    void noDeviceAnswersMinusOne() {
        ArRobot bare = Cycles.p3dxRobot();
        Cycles.cycle(bare, 100, 0, 0, 0);
        assertEquals(-1, bare.checkRangeDevicesCurrentPolar(-90, 90));
        assertEquals(-1, bare.checkRangeDevicesCumulativePolar(-90, 90));
        assertEquals(-1, bare.checkRangeDevicesCurrentBox(0, -1000, 1000, 1000));
        assertEquals(-1, bare.checkRangeDevicesCumulativeBox(0, -1000, 1000, 1000));
    }

    @Test
    void theNearestDeviceAnswersWithItsAngle() {
        double[] angle = {99};
        assertEquals(Math.hypot(800, 800), robot.checkRangeDevicesCurrentPolar(-90, 90, angle), 1e-9);
        assertEquals(45, angle[0], 1e-9);
        assertEquals(Math.hypot(800, 800), robot.checkRangeDevicesCumulativePolar(-90, 90), 1e-9);
    }

    @Test
    void aDeviceWithNothingThereCountsWithItsMaximumRange() {
        // only "far" has a reading in (-10, 10); "near" answers its 3000 maximum, more than 2000
        assertEquals(2000, robot.checkRangeDevicesCurrentPolar(-10, 10), 1e-9);
        // behind the robot: neither has one, the smaller maximum range wins
        assertEquals(3000, robot.checkRangeDevicesCurrentPolar(170, -170), 1e-9);
    }

    @Test
    void theBoxGivesTheReadingInTheRobotsFrame() {
        ArPose at = new ArPose();
        assertEquals(2000, robot.checkRangeDevicesCurrentBox(1000, -100, 3000, 100, at), 1e-9);
        assertEquals(2000, at.getX(), 1e-9);
        assertEquals(0, at.getY(), 1e-9);
        assertEquals(Math.hypot(800, 800), robot.checkRangeDevicesCumulativeBox(0, 0, 1000, 1000, at), 1e-9);
        assertEquals(800, at.getY(), 1e-9);
    }

    @Test
    void findRangeDeviceStillFindsBoth() {
        assertSame(near, robot.findRangeDevice("near"));
    }
}
