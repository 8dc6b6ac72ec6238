package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;

/**
 * A sonar ring fired in sequence: only the transducers a state marks as fired get new data; the
 * others keep their range and are not new (ARIA's isSonarNew: the reading's counter is the robot's).
 */
class SonarSequenceCycleTest {
    private static void cycle(ArRobot robot, long timeMs, int range, Long fired) {
        int[] sonar = new int[16];
        Arrays.fill(sonar, range);
        robot.responded(new RobotSensorResponse(new RobotState(robot.getCounter() + 1, timeMs, 0, 0, 0,
                0, 0, 0, 0, false, 0).with(SonarReading.PART, new SonarReading(sonar, fired))));
    }

    @Test
    void onlyTheFiredTransducersAreNew() {
        ArRobot robot = Cycles.p3dxRobot();
        cycle(robot, 100, 2000, null);
        cycle(robot, 200, 1500, 1L << 3 | 1L << 11);
        assertTrue(robot.isSonarNew(3));
        assertTrue(robot.isSonarNew(11));
        assertFalse(robot.isSonarNew(4));
        assertEquals(1500, robot.getSonarRange(3));
        assertEquals(2000, robot.getSonarRange(4), "sonar 4 did not fire: its reading stays");
        assertEquals(1, robot.getSonarReading(4).getCounterTaken());
    }

    @Test
    void theSonarDeviceTakesOnlyTheNewReadings() {
        ArRobot robot = Cycles.p3dxRobot();
        ArSonarDevice device = new ArSonarDevice();
        robot.addRangeDevice(device);
        cycle(robot, 100, 2000, null);
        assertEquals(16, device.getRawReadings().size());
        cycle(robot, 200, 1500, 1L << 3 | 1L << 11);
        assertEquals(2, device.getRawReadings().size());
        assertEquals(1500, device.getRawReadings().get(0).getRange());
    }

    @Test
    void theP3dxFileGivesAFortyMillisecondCycle() {
        ArRobot robot = new ArRobot("r", "127.0.0.1", 5000, ClosestSonarTest.p3dxFile().toString());
        assertEquals(40, robot.getSonarCycle());
        assertEquals(0, Cycles.p3dxRobot().getSonarCycle(), "parameters without a file fire every step");
    }
}
