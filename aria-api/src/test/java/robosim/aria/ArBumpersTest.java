package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.RobotStates;

/**
 * The stall value's layout (ARIA's ArRobot.h / ArBumpers.cpp) and ArBumpers' readings, from the
 * body's six contact sectors. The shipped p3dx.p declares front and rear rings of five bumpers.
 */
class ArBumpersTest {
    private static final int[] NONE = new int[0];

    private static ArRobot p3dxWithRings() {
        return new ArRobot("r", "127.0.0.1", 5000, ClosestSonarTest.p3dxFile().toString());
    }

    private static void cycle(ArRobot robot, long timeMs, double x, double y, double th, boolean stalled, int sectors) {
        robot.responded(new RobotSensorResponse(RobotStates.of(robot.getCounter() + 1, timeMs, x, y, th,
                0, 0, 0, 0, stalled, NONE, 0, NONE, null, List.of(), List.of(), sectors)));
    }

    @Test
    void aStallSetsBothMotorBits() {
        ArRobot robot = p3dxWithRings();
        cycle(robot, 100, 0, 0, 0, true, 0);
        assertEquals(0x101, robot.getStallValue());
        assertTrue(robot.isLeftMotorStalled());
        assertTrue(robot.isRightMotorStalled());
        cycle(robot, 200, 0, 0, 0, false, 0);
        assertEquals(0, robot.getStallValue());
        assertFalse(robot.isLeftMotorStalled());
    }

    @ParameterizedTest(name = "sector {0} gives stall value {1}")
    @CsvSource({
        // sector 0 (dead ahead, ±30°) holds front bumpers 1, 2, 3 (27°, 0°, −27°): bits 10, 11, 12
        "0, 7168",
        // sector 1 (30..90°) holds front bumper 0 (54°): bit 9
        "1, 512",
        // sector 5 (−90..−30°) holds front bumper 4 (−54°): bit 13
        "5, 8192",
        // sector 3 (behind) holds rear bumpers 1, 2, 3 (207°, 180°, 153°): bits 2, 3, 4
        "3, 28",
        // sector 4 (210..270°) holds rear bumper 0 (234°): bit 1
        "4, 2",
        // sector 2 (90..150°) holds rear bumper 4 (126°): bit 5
        "2, 32"})
    void eachSectorPressesTheBumpersCentredInIt(int sector, int expected) {
        ArRobot robot = p3dxWithRings();
        cycle(robot, 100, 0, 0, 0, false, 1 << sector);
        assertEquals(expected, robot.getStallValue());
    }

    @Test
    void aRobotWithoutRingsReportsNoBumpers() {
        ArRobot robot = Cycles.p3dxRobot();
        cycle(robot, 100, 0, 0, 0, false, 0b111111);
        assertEquals(0, robot.getStallValue());
        assertFalse(robot.hasFrontBumpers());
        assertFalse(robot.isFrontBumperTriggered());
    }

    @Test
    void frontAndRearTriggersReadTheirBytes() {
        ArRobot robot = p3dxWithRings();
        cycle(robot, 100, 0, 0, 0, false, 1);
        assertTrue(robot.isFrontBumperTriggered());
        assertFalse(robot.isRearBumperTriggered());
        assertEquals(5, robot.getNumFrontBumpers());
    }

    @Test
    void aPressedBumperAddsAReadingOnTheRobotsCircle() {
        ArRobot robot = p3dxWithRings();
        ArBumpers bumpers = new ArBumpers();
        robot.addRangeDevice(bumpers);
        // the robot at (1000, 0) facing +y; contact in sector 1 presses front bumper 0, at 54°
        cycle(robot, 100, 1000, 0, 90, false, 1 << 1);
        List<ArPose> current = bumpers.getCurrentBuffer();
        assertEquals(1, current.size());
        double th = Math.toRadians(90 + 54);
        assertEquals(1000 + 250 * Math.cos(th), current.get(0).getX(), 1e-9);
        assertEquals(250 * Math.sin(th), current.get(0).getY(), 1e-9);
        assertTrue(bumpers.getCumulativeBuffer().isEmpty());
    }

    @Test
    void bumpsAreKeptFifteenSeconds() {
        ArRobot robot = p3dxWithRings();
        ArBumpers bumpers = new ArBumpers();
        robot.addRangeDevice(bumpers);
        cycle(robot, 100, 0, 0, 0, false, 1);
        assertEquals(3, bumpers.getCurrentBuffer().size());
        cycle(robot, 15_100, 0, 0, 0, false, 0);
        assertEquals(3, bumpers.getCurrentBuffer().size());
        cycle(robot, 15_101, 0, 0, 0, false, 0);
        assertTrue(bumpers.getCurrentBuffer().isEmpty());
    }
}
