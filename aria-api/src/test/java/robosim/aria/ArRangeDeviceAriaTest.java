package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.junit.jupiter.api.Test;

/** ArRangeDevice's ARIA calls (ArRangeDevice.h/.cpp) beyond the buffers and queries tested elsewhere. */
class ArRangeDeviceAriaTest {
    private static List<Double> xs(List<ArPoseWithTime> readings) {
        return readings.stream().map(ArPoseWithTime::getX).toList();
    }

    @Test
    void ariasConstructorKeepsAriasDefaultsAndFixesTheName() {
        ArRangeDevice d = new ArRangeDevice(10, 20, "my sonar\t2", 5000);
        assertEquals("my_sonar_2", d.getName());
        assertEquals(10, d.getCurrentBufferSize());
        assertEquals(20, d.getCumulativeBufferSize());
        assertEquals(5000, d.getMaxRange());
        assertEquals(0, d.getMaxSecondsToKeepCurrent());
        assertEquals(0, d.getMaxSecondsToKeepCumulative());
        assertEquals(0, d.getMaxDistToKeepCumulative());
        assertEquals(0, d.getMinDistBetweenCumulative());
        assertEquals(0, d.getMinDistBetweenCurrent());
        assertEquals(0, d.getMaxInsertDistCumulative());
        assertFalse(d.isLocationDependent());
        ArRangeDevice all = new ArRangeDevice(1, 2, "forbidden", 100, 5, 15, 3000, true);
        assertEquals(5, all.getMaxSecondsToKeepCurrent());
        assertEquals(15, all.getMaxSecondsToKeepCumulative());
        assertEquals(3000, all.getMaxDistToKeepCumulative());
        assertTrue(all.isLocationDependent());
        assertFalse(new ArRangeDevice("x", 100).isLocationDependent());
    }

    @Test
    void ariasDevicesKeepReadingsForEver() {
        ArRobot robot = Cycles.p3dxRobot();
        ArRangeDevice d = new ArRangeDevice(10, 10, "d", 5000);
        robot.addRangeDevice(d);
        Cycles.cycle(robot, 0, 0, 0, 0);
        d.addReading(4000, 0);
        Cycles.cycle(robot, 60_000, 0, 0, 0);
        assertEquals(1, d.getCurrentBuffer().size());
        assertEquals(1, d.getCumulativeBuffer().size(), "no age and no distance limit");
    }

    @Test
    void minDistBetweenCurrentRefreshesTheOlderReadingInsteadOfAdding() {
        ArRobot robot = Cycles.p3dxRobot();
        ArRangeDevice d = new ArRangeDevice(10, 10, "d", 5000);
        robot.addRangeDevice(d);
        Cycles.cycle(robot, 100, 0, 0, 0);
        boolean[] added = {false};
        d.addReading(1000, 0, added);
        assertTrue(added[0]);
        d.addReading(2000, 0, added);
        d.setMinDistBetweenCurrent(50);
        Cycles.cycle(robot, 300, 0, 0, 0);
        d.addReading(1030, 0, added);
        assertFalse(added[0]);
        assertEquals(List.of(2000.0, 1000.0), xs(d.getCurrentReadings()), "not added; the old one keeps its place");
        assertEquals(300, d.getCurrentReadings().get(1).getTime().getTimeMs(), "its time refreshed");
        assertEquals(100, d.getCurrentReadings().get(0).timeMs());
        d.addReading(1050, 0, added);
        assertTrue(added[0], "exactly the distance away is added");
        assertEquals(3, d.getCurrentBuffer().size());
    }

    @Test
    void maxInsertDistCumulativeKeepsFarReadingsOutOfTheCumulativeBuffer() {
        ArRobot robot = Cycles.p3dxRobot();
        ArRangeDevice d = new ArRangeDevice(10, 10, "d", 5000);
        robot.addRangeDevice(d);
        Cycles.cycle(robot, 100, 1000, 0, 0);
        d.setMaxInsertDistCumulative(500);
        d.addReading(1400, 0);
        d.addReading(1600, 0);
        assertEquals(List.of(1600.0, 1400.0), xs(d.getCurrentReadings()));
        assertEquals(List.of(1400.0), xs(d.getCumulativeReadings()));
    }

    @Test
    void maxInsertDistCumulativeNeedsARobot() {
        ArRangeDevice d = new ArRangeDevice(10, 10, "d", 5000);
        d.setMaxInsertDistCumulative(500);
        d.addReading(1600, 0);
        assertEquals(1, d.getCumulativeReadings().size(), "as ARIA's, the rule applies only with a robot");
    }

    @Test
    void clearCumulativeOlderThanKeepsExactlyThatOld() {
        ArRobot robot = Cycles.p3dxRobot();
        ArRangeDevice d = new ArRangeDevice(10, 10, "d", 5000);
        robot.addRangeDevice(d);
        Cycles.cycle(robot, 1000, 0, 0, 0);
        d.addReading(100, 0);
        Cycles.cycle(robot, 2000, 0, 0, 0);
        d.addReading(200, 0);
        Cycles.cycle(robot, 3000, 0, 0, 0);
        d.clearCumulativeOlderThan(2000);
        assertEquals(List.of(200.0, 100.0), xs(d.getCumulativeReadings()));
        d.clearCumulativeOlderThan(1999);
        assertEquals(List.of(200.0), xs(d.getCumulativeReadings()));
        d.clearCumulativeOlderThanSeconds(0);
        assertTrue(d.getCumulativeReadings().isEmpty());
        assertEquals(2, d.getCurrentReadings().size(), "the current buffer is left");
    }

    @Test
    void readingsCarryTheirTimeAndTheRobotsPose() {
        ArRobot robot = Cycles.p3dxRobot();
        ArRangeDevice d = new ArRangeDevice(10, 10, "d", 5000);
        robot.addRangeDevice(d);
        Cycles.cycle(robot, 700, 10, 20, 30);
        d.addReading(500, 600);
        ArPoseWithTime r = d.getCurrentReadings().get(0);
        assertEquals(500, r.getX());
        assertEquals(600, r.getY());
        assertEquals(0, r.getTh());
        assertEquals(700, r.getTime().getTimeMs());
        assertEquals(new ArPose(10, 20, 30), r.robotPose());
        r.robotPose().setX(99);
        assertEquals(10, r.robotPose().getX(), "the robot's pose is a copy");
    }

    @Test
    void adjustedRawReadingsAreNoneWithoutAnOdometryDelay() {
        assertNull(new ArRangeDevice("d", 100).getAdjustedRawReadings());
    }

    @Test
    void theDeviceLockHoldsOffTheCyclesUpdate() throws Exception {
        ArRobot robot = Cycles.p3dxRobot();
        int[] processed = {0};
        ArRangeDevice d = new ArRangeDevice("d", 5000) {
            @Override
            protected void processReadings() {
                processed[0]++;
            }
        };
        robot.addRangeDevice(d);
        Cycles.cycle(robot, 100, 0, 0, 0);
        assertEquals(1, processed[0]);
        assertEquals(0, d.lockDevice());
        CompletableFuture<Void> cycle = CompletableFuture.runAsync(() -> Cycles.cycle(robot, 200, 0, 0, 0));
        try {
            cycle.get(300, TimeUnit.MILLISECONDS);
            throw new AssertionError("the cycle ran while the device was locked");
        } catch (TimeoutException expected) {
            // the cycle waits
        }
        assertEquals(1, processed[0]);
        assertEquals(ArRangeDevice.STATUS_ALREADY_LOCKED,
                CompletableFuture.supplyAsync(d::tryLockDevice).get(5, TimeUnit.SECONDS));
        assertEquals(0, d.unlockDevice());
        cycle.get(5, TimeUnit.SECONDS);
        assertEquals(2, processed[0]);
        assertEquals(ArRangeDevice.STATUS_FAILED, d.unlock(), "not held by this thread");
        assertEquals(0, d.tryLock());
        assertEquals(0, d.lock(), "reentrant");
        assertEquals(0, d.unlock());
        assertEquals(0, d.unlock());
    }

    @Test
    void logConfigAndLogDataWriteTheDevicesState() {
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        ArLog.LogLevel level = ArLog.getLogLevel();
        try {
            ArLog.setStream(new java.io.PrintStream(out, true));
            ArLog.setLogLevel(ArLog.Normal);
            ArRangeDevice d = new ArRangeDevice(10, 10, "d", 5000, 5, 15, 3000, false);
            d.addReading(1000, 0);
            d.logConfig(ArLog.Normal, "> ");
            d.logData();
        } finally {
            ArLog.setStream(null);
            ArLog.setLogLevel(level);
        }
        String text = out.toString();
        assertTrue(text.contains("> d MaxRange=5000 MaxSecondsToKeepCurrent=5"), text);
        assertTrue(text.contains("MaxSecondsToKeepCumulative=15"), text);
        assertTrue(text.contains("d Current: 1 readings: (1000, 0)"), text);
        assertTrue(text.contains("d Cumulative: 1 readings"), text);
    }
}
