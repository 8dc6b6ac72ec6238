package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The laser's buffers by ARIA's rules (ArLaser.cpp) and the defaults of ARIA's LMS200 driver
 * (ArLMS2xx.cpp: keep cumulative 6000 mm and 30 s, 200 mm between cumulative readings, insert
 * within 3000 mm, clean within 75 mm every 1000 ms). The p3dx's laser sits 18 mm ahead of its
 * centre; the robot stands at the origin facing +x; a scan of 181 readings with 8000 (nothing) but
 * where a test says otherwise.
 */
class ArSickBufferTest {
    private static final int[] NO_SONAR = new int[0];
    private ArRobot robot;
    private ArSick sick;

    @BeforeEach
    void laserOnAP3dx() {
        robot = Cycles.p3dxRobot();
        sick = new ArSick();
        robot.addRangeDevice(sick);
    }

    private static int[] scanWith(int... beamAndRange) {
        int[] s = new int[181];
        Arrays.fill(s, 8000);
        for (int i = 0; i < beamAndRange.length; i += 2) {
            s[beamAndRange[i]] = beamAndRange[i + 1];
        }
        return s;
    }

    private void scan(long timeMs, int... beamAndRange) {
        Cycles.cycle(robot, timeMs, 0, 0, 0, NO_SONAR, scanWith(beamAndRange));
    }

    @Test
    void theDefaultsAreAriasLms200s() {
        assertEquals(6000, sick.getMaxDistToKeepCumulative());
        assertEquals(200, sick.getMinDistBetweenCumulative());
        assertEquals(30, sick.getMaxSecondsToKeepCumulative());
        assertEquals(3000, sick.getMaxInsertDistCumulative());
        assertEquals(75, sick.getCumulativeCleanDist());
        assertEquals(1000, sick.getCumulativeCleanInterval());
        assertEquals(0, sick.getMaxSecondsToKeepCurrent());
        assertEquals(361, sick.getCurrentBufferSize());
        assertEquals(200, sick.getCumulativeBufferSize());
    }

    @Test
    void theCurrentBufferHoldsTheLatestScanOnly() {
        Cycles.cycle(robot, 100, 0, 0, 0, NO_SONAR, scanWith(10, 2000, 20, 2000, 30, 2000));
        assertEquals(3, sick.getCurrentBuffer().size());
        scan(200, 90, 1000);
        List<ArPose> current = sick.getCurrentBuffer();
        assertEquals(1, current.size());
        assertEquals(1018, current.get(0).getX(), 1e-9);
    }

    @Test
    void aCycleWithoutAScanLeavesTheCurrentBuffer() {
        scan(100, 90, 1000);
        Cycles.cycle(robot, 200, 0, 0, 0);
        assertEquals(1, sick.getCurrentBuffer().size());
    }

    @Test
    void readingsWithinTheInsertDistanceEnterTheCumulativeBuffer() {
        scan(100, 90, 3000);
        assertEquals(1, sick.getCumulativeBuffer().size());
    }

    @Test
    void readingsBeyondTheInsertDistanceStayOut() {
        scan(100, 90, 3001);
        assertTrue(sick.getCumulativeBuffer().isEmpty());
        assertEquals(1, sick.getCurrentBuffer().size());
    }

    @Test
    void aReadingCloserThan200MmToAKeptOneStaysOut() {
        scan(100, 90, 1000);
        // 199 mm farther along the same beam: too close; no clean is due 100 ms on
        scan(200, 90, 1199);
        assertEquals(1, sick.getCumulativeBuffer().size());
        scan(300, 90, 1200);
        assertEquals(2, sick.getCumulativeBuffer().size());
    }

    /** A scan that hits a ring round the laser: every beam ends at {@code range}. */
    private void ringScan(long timeMs, int range) {
        int[] s = new int[181];
        Arrays.fill(s, range);
        Cycles.cycle(robot, timeMs, 0, 0, 0, NO_SONAR, s);
    }

    @Test
    void noCleanIsDueUntilMoreThanASecondHasPassed() {
        scan(100, 90, 1000);
        // exactly 1000 ms later is not more than the interval: the beam to 2000 clears nothing
        scan(1100, 90, 2000);
        assertEquals(2, sick.getCumulativeBuffer().size());
    }

    @Test
    void aBeamClearsTheReadingsItPassesThrough() {
        scan(100, 90, 1000);
        // 1001 ms after the first scan a clean is due: the beam to 2500 passes through (1018, 0)
        ringScan(1101, 2500);
        List<ArPose> cumulative = sick.getCumulativeBuffer();
        assertTrue(!cumulative.isEmpty());
        for (ArPose p : cumulative) {
            assertTrue(Math.hypot(p.getX() - 18, p.getY()) > 2499, "kept " + p);
        }
    }

    @Test
    void aReadingNearTheBeamsEndIsNotCleared() {
        scan(100, 90, 1000);
        // the beams end 40 mm beyond the kept reading: within 50 mm of their ends, it stays
        ringScan(1101, 1040);
        assertTrue(sick.getCumulativeBuffer().stream().anyMatch(p -> p.getX() == 1018 && p.getY() == 0),
                sick.getCumulativeBuffer().toString());
    }

    @Test
    void cumulativeReadingsAreKeptThirtySeconds() {
        scan(100, 90, 1000);
        Cycles.cycle(robot, 30_100, 0, 0, 0);
        assertEquals(1, sick.getCumulativeBuffer().size());
        Cycles.cycle(robot, 30_101, 0, 0, 0);
        assertTrue(sick.getCumulativeBuffer().isEmpty());
    }

    @Test
    void cumulativeReadingsAreKeptWithin6000MmOfTheRobot() {
        scan(100, 90, 1000);
        Cycles.cycle(robot, 200, -4982, 0, 0);
        assertEquals(1, sick.getCumulativeBuffer().size());
        Cycles.cycle(robot, 300, -4983, 0, 0);
        assertTrue(sick.getCumulativeBuffer().isEmpty());
    }

    @Test
    void aWiderInsertDistanceLetsFartherReadingsInAndOneOrLessLetsAnyIn() {
        sick.setMaxInsertDistCumulative(5000);
        assertEquals(5000, sick.getMaxInsertDistCumulative());
        scan(100, 90, 4000);
        assertEquals(1, sick.getCumulativeBuffer().size());
        sick.setMaxInsertDistCumulative(1);
        scan(200, 45, 5900);
        assertEquals(2, sick.getCumulativeBuffer().size(), "any reading that hit something");
    }

    @Test
    void aCleanIntervalOfZeroCleansWithEveryScan() {
        scan(100, 90, 1000);
        assertEquals(1, sick.getCumulativeBuffer().size());
        sick.setCumulativeCleanInterval(0);
        assertEquals(0, sick.getCumulativeCleanInterval());
        ringScan(200, 2500); // 100 ms later: cleaned all the same
        assertTrue(sick.getCumulativeBuffer().stream().noneMatch(p -> p.getX() == 1018 && p.getY() == 0),
                sick.getCumulativeBuffer().toString());
    }

    @Test
    void aCleanDistanceBelowOneNeverCleans() {
        sick.setCumulativeCleanDist(0);
        assertEquals(0, sick.getCumulativeCleanDist());
        scan(100, 90, 1000);
        ringScan(1101, 2500); // a clean is due, but clears nothing
        assertTrue(sick.getCumulativeBuffer().stream().anyMatch(p -> p.getX() == 1018 && p.getY() == 0),
                sick.getCumulativeBuffer().toString());
    }
}
