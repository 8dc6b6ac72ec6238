package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.BatteryReading;
import robosim.protocol.RobotState;

/**
 * The battery as ARIA's ArRobot reads it: the latest reading, and the running average of the latest
 * 20, starting from ARIA's 13 V before the first reading; the state of charge once one above 0 came.
 */
class ArRobotBatteryTest {
    private static void cycle(ArRobot robot, BatteryReading battery) {
        RobotState s = new RobotState(robot.getCounter() + 1, 100L * (robot.getCounter() + 1), 0, 0, 0, 0, 0, 0, 0,
                false, 0).with(BatteryReading.PART, battery);
        robot.responded(new RobotSensorResponse(s));
    }

    @Test
    void beforeAnyReadingTheBatteryReadsAriasThirteenVoltsAndNoCharge() {
        ArRobot robot = Cycles.p3dxRobot();
        assertEquals(13.0, robot.getBatteryVoltage());
        assertEquals(13.0, robot.getBatteryVoltageNow());
        assertEquals(13.0, robot.getRealBatteryVoltage());
        assertFalse(robot.haveStateOfCharge());
        assertEquals(0, robot.getStateOfCharge());
    }

    @Test
    void theVoltageIsTheRunningAverageOfTheLatestTwentyReadings() {
        ArRobot robot = Cycles.p3dxRobot();
        cycle(robot, new BatteryReading(12.0, 90));
        assertEquals(12.0, robot.getBatteryVoltageNow());
        assertEquals(12.5, robot.getBatteryVoltage(), 1e-12, "ARIA's 13 V and the first reading");
        for (int i = 0; i < 19; i++) {
            cycle(robot, new BatteryReading(12.0, 90));
        }
        assertEquals(12.0, robot.getBatteryVoltage(), 1e-12, "20 readings: the 13 V has gone");
        assertEquals(12.0, robot.getRealBatteryVoltage(), 1e-12);
        assertEquals(12.0, robot.getRealBatteryVoltageNow());
        assertTrue(robot.haveStateOfCharge());
        assertTrue(robot.hasStateOfCharge());
        assertEquals(90, robot.getStateOfCharge());
    }

    @Test
    void theNumberOfReadingsAveragedCanBeSetAsInAria() {
        ArRobot robot = Cycles.p3dxRobot();
        assertEquals(20, robot.getBatteryVoltageAverageOfNum());
        robot.setBatteryVoltageAverageOfNum(2);
        cycle(robot, new BatteryReading(12.2, 90));
        cycle(robot, new BatteryReading(12.0, 90));
        cycle(robot, new BatteryReading(11.8, 90));
        assertEquals(11.9, robot.getBatteryVoltage(), 1e-12);
        assertEquals(2, robot.getBatteryVoltageAverageOfNum());
        assertEquals(20, robot.getRealBatteryVoltageAverageOfNum(), "the real voltage's average is its own");
        robot.setRealBatteryVoltageAverageOfNum(1);
        assertEquals(11.8, robot.getRealBatteryVoltage(), 1e-12);
        assertThrows(IllegalArgumentException.class, () -> robot.setBatteryVoltageAverageOfNum(0));
    }

    @Test
    void aStateWithoutABatteryLeavesTheReadingsAsTheyWere() {
        ArRobot robot = Cycles.p3dxRobot();
        cycle(robot, new BatteryReading(12.4, 0));
        cycle(robot, null);
        assertEquals(12.4, robot.getBatteryVoltageNow());
        assertFalse(robot.haveStateOfCharge(), "a charge of 0 is a robot that does not report one, as in ARIA");
    }
}
