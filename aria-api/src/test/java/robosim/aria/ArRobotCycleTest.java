package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.RobotStates;
import robosim.params.ParameterFileReader;

/** ARIA's rules for the robot's cycle, its counter, sonar readings and tasks. */
class ArRobotCycleTest {
    private final ArRobot robot = new ArRobot("r", "127.0.0.1", 5000, ParameterFileReader.read(ClosestSonarTest.p3dxFile()));

    private static int[] ranges(int base) {
        int[] r = new int[16];
        for (int i = 0; i < 16; i++) {
            r[i] = base + 10 * i;
        }
        return r;
    }

    private void cycle(long step, double vel, double rotVel, int[] sonar) {
        robot.responded(new RobotSensorResponse(RobotStates.of(step, step * 100, 1000 + step, 2000, 30, vel, rotVel,
                vel, vel, false, sonar, 0, new int[0], null)));
    }

    @Test
    void theCounterGoesUpOncePerCycle() {
        assertEquals(0, robot.getCounter());
        cycle(1, 0, 0, ranges(500));
        cycle(2, 0, 0, ranges(500));
        assertEquals(2, robot.getCounter());
    }

    @Test
    void aSonarIsNewOnlyInTheCycleItsReadingArrived() {
        assertFalse(robot.isSonarNew(0), "never reported");
        cycle(1, 0, 0, ranges(500));
        assertTrue(robot.isSonarNew(0));
        assertEquals(robot.getCounter(), robot.getSonarReading(0).getCounterTaken());
        cycle(2, 0, 0, new int[0]); // sonars off: no readings this cycle
        assertFalse(robot.isSonarNew(0), "the reading is from the cycle before");
        assertEquals(500, robot.getSonarRange(0), "the last reading stays");
        assertFalse(robot.isSonarNew(-1));
        assertFalse(robot.isSonarNew(16));
    }

    @Test
    void aSonarThatNeverReportedReads5000AndIsIgnored() {
        assertEquals(5000, robot.getSonarRange(7));
        assertTrue(robot.getSonarReading(7).getIgnoreThisReading());
        cycle(1, 0, 0, ranges(500));
        assertFalse(robot.getSonarReading(7).getIgnoreThisReading());
        assertEquals(570, robot.getSonarRange(7));
    }

    @Test
    void badSonarIndicesGiveMinusOneAndNull() {
        assertEquals(-1, robot.getSonarRange(16));
        assertNull(robot.getSonarReading(16));
        assertNull(robot.getSonarReading(-1));
    }

    @Test
    void aSonarReadingKnowsWhereItsEchoLies() {
        cycle(1, 0, 0, ranges(1000));
        ArSensorReading r = robot.getSonarReading(3); // at (166, 27), 10°, range 1030
        assertEquals(166 + 1030 * Math.cos(Math.toRadians(10)), r.getLocalX(), 1e-9);
        assertEquals(27 + 1030 * Math.sin(Math.toRadians(10)), r.getLocalY(), 1e-9);
        double th = Math.toRadians(30);
        assertEquals(1001 + r.getLocalX() * Math.cos(th) - r.getLocalY() * Math.sin(th), r.getX(), 1e-9);
        assertEquals(2000 + r.getLocalX() * Math.sin(th) + r.getLocalY() * Math.cos(th), r.getY(), 1e-9);
        assertEquals(1001, r.getPoseTaken().getX(), 1e-9);
        assertEquals(10, r.getSensorTh(), 1e-9);
        assertEquals(100, r.getTimeTaken());
    }

    @Test
    void sensorTasksRunBeforeUserTasksAndHigherPositionsFirst() {
        List<String> order = new ArrayList<>();
        robot.addUserTask("user-low", 10, () -> order.add("user-low"));
        robot.addUserTask("user-high", 90, () -> order.add("user-high"));
        robot.addSensorInterpTask("sensor", 50, () -> order.add("sensor:" + robot.isSonarNew(0)));
        robot.addUserTask("user-high-2", 90, () -> order.add("user-high-2"));
        cycle(1, 0, 0, ranges(500));
        assertEquals(List.of("sensor:true", "user-high", "user-high-2", "user-low"), order);
        assertTrue(robot.remUserTask("user-high"));
        assertFalse(robot.remUserTask("user-high"));
        order.clear();
        cycle(2, 0, 0, ranges(500));
        assertEquals(List.of("sensor:true", "user-high-2", "user-low"), order);
    }

    @Test
    void aTaskThatThrowsIsRemovedAndTheOthersRun() {
        List<String> ran = new ArrayList<>();
        robot.addUserTask("bad", 50, () -> {
            throw new IllegalStateException("broken");
        });
        robot.addUserTask("good", 10, () -> ran.add("good"));
        cycle(1, 0, 0, ranges(500));
        cycle(2, 0, 0, ranges(500));
        assertEquals(List.of("good", "good"), ran);
    }

    @Test
    void tasksRunUnderTheRobotsLock() {
        List<Boolean> locked = new ArrayList<>();
        robot.addUserTask("check", 0, () -> locked.add(robot.isLockedByMe()));
        cycle(1, 0, 0, ranges(500));
        assertEquals(List.of(true), locked);
    }

    @Test
    void isStoppedUsesAriasThresholds() {
        cycle(1, 4, 1, ranges(500));
        assertTrue(robot.isStopped(), "4 mm/s and 1 deg/s count as stopped");
        cycle(2, 4.5, 0, ranges(500));
        assertFalse(robot.isStopped());
        cycle(3, 0, -1.5, ranges(500));
        assertFalse(robot.isStopped());
    }

    @Test
    void sleepingWhileHoldingTheLockIsAnError() {
        robot.lock();
        try {
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> robot.sleepSimulated(100));
            assertTrue(e.getMessage().contains("unlock() first"), e.getMessage());
        } finally {
            robot.unlock();
        }
    }

    @Test
    void rangeDevicesKnowTheirRobot() {
        ArRangeDevice d = new ArRangeDevice("dev", 1000);
        robot.addRangeDevice(d);
        assertSame(robot, d.getRobot());
        assertSame(d, robot.findRangeDevice("dev"));
        robot.remRangeDevice(d);
        assertNull(d.getRobot());
        assertTrue(robot.getRangeDeviceList().isEmpty());
    }

    @Test
    void dimensionsAndLimitsComeFromTheParameterFile() {
        ArRobot at = new ArRobot("a", "127.0.0.1", 5000,
                ParameterFileReader.read(ClosestSonarTest.p3dxFile().resolveSibling("p3at.p")));
        assertEquals(500, at.getRobotRadius());
        assertEquals(505, at.getRobotWidth());
        assertEquals(626, at.getRobotLength());
        assertEquals(1200, at.getMaxTransVel());
        assertEquals(300, at.getMaxRotVel());
        assertEquals(16, at.getNumSonar());
        assertEquals("a", at.getName());
        at.setMaxTransVel(5000);
        assertEquals(1200, at.getMaxTransVel(), "within the file's maximum");
    }

    @Test
    void theHeatSensorReadsNothingBeforeItsFirstReading() {
        ArHeatSensor heat = new ArHeatSensor(90, 5000);
        assertFalse(heat.senses());
        assertThrows(IllegalArgumentException.class, () -> new ArHeatSensor(0, 5000));
        assertThrows(IllegalArgumentException.class, () -> new ArHeatSensor(90, -1));
    }
}
