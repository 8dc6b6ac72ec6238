package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** ARIA's pruning: by age (current 5 s, cumulative 15 s), by distance (3000 mm) and by merging (50 mm). */
class ArRangeDevicePruneTest {
    private ArRobot robot;
    private ArRangeDevice device;

    @BeforeEach
    void attachedAtTimeZero() {
        robot = Cycles.p3dxRobot();
        device = new ArRangeDevice("test", 5000, 10, 10);
        robot.addRangeDevice(device);
        Cycles.cycle(robot, 0, 0, 0, 0);
        device.addReading(1000, 0);
    }

    @Test
    void theDefaultsAreArias() {
        assertEquals(5, device.getMaxSecondsToKeepCurrent());
        assertEquals(15, device.getMaxSecondsToKeepCumulative());
        assertEquals(3000, device.getMaxDistToKeepCumulative());
        assertEquals(50, device.getMinDistBetweenCumulative());
    }

    @Test
    void aCurrentReadingGoesWhenOlderThanFiveSeconds() {
        Cycles.cycle(robot, 5000, 0, 0, 0);
        assertEquals(1, device.getCurrentBuffer().size(), "exactly 5 s old is kept");
        Cycles.cycle(robot, 5100, 0, 0, 0);
        assertTrue(device.getCurrentBuffer().isEmpty());
        assertEquals(1, device.getCumulativeBuffer().size(), "the cumulative buffer keeps it longer");
    }

    @Test
    void theCurrentAgeIsSettable() {
        device.setMaxSecondsToKeepCurrent(1);
        Cycles.cycle(robot, 1100, 0, 0, 0);
        assertTrue(device.getCurrentBuffer().isEmpty());
    }

    @Test
    void aCumulativeReadingGoesWhenOlderThanFifteenSeconds() {
        Cycles.cycle(robot, 15000, 0, 0, 0);
        assertEquals(1, device.getCumulativeBuffer().size(), "exactly 15 s old is kept");
        Cycles.cycle(robot, 15100, 0, 0, 0);
        assertTrue(device.getCumulativeBuffer().isEmpty());
    }

    @Test
    void theCumulativeAgeIsSettable() {
        device.setMaxSecondsToKeepCumulative(30);
        Cycles.cycle(robot, 29900, 0, 0, 0);
        assertEquals(1, device.getCumulativeBuffer().size());
    }

    @Test
    void aCumulativeReadingGoesWhenFartherThan3000MmFromTheRobot() {
        Cycles.cycle(robot, 100, -1900, 0, 0);
        assertEquals(1, device.getCumulativeBuffer().size(), "2900 mm away is kept");
        Cycles.cycle(robot, 200, -2100, 0, 0);
        assertTrue(device.getCumulativeBuffer().isEmpty(), "3100 mm away goes");
        assertEquals(1, device.getCurrentBuffer().size(), "distance does not prune the current buffer");
    }

    @Test
    void aReadingFartherThan3000MmGoesIntoTheCurrentBufferOnly() {
        device.addReading(0, 3100);
        assertEquals(2, device.getCurrentBuffer().size());
        assertEquals(List.of(1000.0), device.getCumulativeBuffer().stream().map(ArPose::getX).toList());
    }

    @Test
    void theCumulativeDistanceIsSettable() {
        device.setMaxDistToKeepCumulative(5000);
        Cycles.cycle(robot, 100, -3900, 0, 0);
        assertEquals(1, device.getCumulativeBuffer().size());
    }

    @Test
    void aNewCumulativeReadingWithin50MmReplacesTheOldOne() {
        device.addReading(1030, 0);
        List<ArPose> cumulative = device.getCumulativeBuffer();
        assertEquals(1, cumulative.size());
        assertEquals(1030, cumulative.get(0).getX(), 1e-9, "the new reading replaces the old");
        assertEquals(2, device.getCurrentBuffer().size(), "the current buffer keeps both");
    }

    @Test
    void aNewCumulativeReadingFartherThan50MmIsAdded() {
        device.addReading(1070, 0);
        assertEquals(2, device.getCumulativeBuffer().size());
    }

    @Test
    void aMergedReadingIsStampedAnew() {
        Cycles.cycle(robot, 10000, 0, 0, 0);
        device.addReading(1020, 0);
        Cycles.cycle(robot, 20000, 0, 0, 0);
        assertEquals(1, device.getCumulativeBuffer().size(), "10 s old, not 20: the merge renewed it");
    }

    @Test
    void theMergeDistanceIsSettable() {
        device.setMinDistBetweenCumulative(0);
        device.addReading(1010, 0);
        assertEquals(2, device.getCumulativeBuffer().size());
    }
}
