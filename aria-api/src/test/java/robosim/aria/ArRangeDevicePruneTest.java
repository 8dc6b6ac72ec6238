package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** ARIA's pruning: by age (current 5 s, cumulative 15 s), by distance (3000 mm) and by merging (50 mm). */
class ArRangeDevicePruneTest {
    private CycleRobot robot;
    private ArRangeDevice device;

    @BeforeEach
    void attachedAtTimeZero() {
        robot = new CycleRobot(CycleRobot.p3dx());
        device = new ArRangeDevice("test", 5000, 10, 10);
        robot.addRangeDevice(device);
        robot.cycle(0, 0, 0, 0);
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
        robot.cycle(5000, 0, 0, 0);
        assertEquals(1, device.getCurrentBuffer().size(), "exactly 5 s old is kept");
        robot.cycle(5100, 0, 0, 0);
        assertTrue(device.getCurrentBuffer().isEmpty());
        assertEquals(1, device.getCumulativeBuffer().size(), "the cumulative buffer keeps it longer");
    }

    @Test
    void theCurrentAgeIsSettable() {
        device.setMaxSecondsToKeepCurrent(1);
        robot.cycle(1100, 0, 0, 0);
        assertTrue(device.getCurrentBuffer().isEmpty());
    }

    @Test
    void aCumulativeReadingGoesWhenOlderThanFifteenSeconds() {
        robot.cycle(15000, 0, 0, 0);
        assertEquals(1, device.getCumulativeBuffer().size(), "exactly 15 s old is kept");
        robot.cycle(15100, 0, 0, 0);
        assertTrue(device.getCumulativeBuffer().isEmpty());
    }

    @Test
    void theCumulativeAgeIsSettable() {
        device.setMaxSecondsToKeepCumulative(30);
        robot.cycle(29900, 0, 0, 0);
        assertEquals(1, device.getCumulativeBuffer().size());
    }

    @Test
    void aCumulativeReadingGoesWhenFartherThan3000MmFromTheRobot() {
        robot.cycle(100, -1900, 0, 0);
        assertEquals(1, device.getCumulativeBuffer().size(), "2900 mm away is kept");
        robot.cycle(200, -2100, 0, 0);
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
        robot.cycle(100, -3900, 0, 0);
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
        robot.cycle(10000, 0, 0, 0);
        device.addReading(1020, 0);
        robot.cycle(20000, 0, 0, 0);
        assertEquals(1, device.getCumulativeBuffer().size(), "10 s old, not 20: the merge renewed it");
    }

    @Test
    void theMergeDistanceIsSettable() {
        device.setMinDistBetweenCumulative(0);
        device.addReading(1010, 0);
        assertEquals(2, device.getCumulativeBuffer().size());
    }
}
