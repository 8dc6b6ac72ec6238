package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** A range device's two buffers: newest first, bounded, the oldest evicted. */
class ArRangeDeviceBufferTest {
    private ArRobot robot;
    private ArRangeDevice device;

    @BeforeEach
    void attached() {
        robot = Cycles.p3dxRobot();
        device = new ArRangeDevice("test", 5000, 3, 4);
        robot.addRangeDevice(device);
        Cycles.cycle(robot, 100, 0, 0, 0);
    }

    /** Readings along the x axis, 100 mm apart, so none merges with another. */
    private void addAlongX(int... xs) {
        for (int x : xs) {
            device.addReading(x, 0);
        }
    }

    private static List<Double> xs(List<ArPose> poses) {
        return poses.stream().map(ArPose::getX).toList();
    }

    @Test
    void theCurrentBufferKeepsTheNewestFirstAndEvictsTheOldest() {
        addAlongX(100, 200, 300, 400, 500);
        assertEquals(List.of(500.0, 400.0, 300.0), xs(device.getCurrentBuffer()));
    }

    @Test
    void theCumulativeBufferKeepsTheNewestFirstAndEvictsTheOldest() {
        addAlongX(100, 200, 300, 400, 500, 600);
        assertEquals(List.of(600.0, 500.0, 400.0, 300.0), xs(device.getCumulativeBuffer()));
    }

    @Test
    void sizesAreWhatWasSet() {
        assertEquals(3, device.getCurrentBufferSize());
        assertEquals(4, device.getCumulativeBufferSize());
        device.setCurrentBufferSize(10);
        device.setCumulativeBufferSize(20);
        assertEquals(10, device.getCurrentBufferSize());
        assertEquals(20, device.getCumulativeBufferSize());
    }

    @Test
    void aSmallerCurrentSizeEvictsTheOldest() {
        addAlongX(100, 200, 300);
        device.setCurrentBufferSize(1);
        assertEquals(List.of(300.0), xs(device.getCurrentBuffer()));
        addAlongX(400);
        assertEquals(List.of(400.0), xs(device.getCurrentBuffer()));
    }

    @Test
    void aSmallerCumulativeSizeEvictsTheOldest() {
        addAlongX(100, 200, 300, 400);
        device.setCumulativeBufferSize(2);
        assertEquals(List.of(400.0, 300.0), xs(device.getCumulativeBuffer()));
    }

    @Test
    void aCumulativeSizeOfZeroKeepsNothing() {
        device.setCumulativeBufferSize(0);
        addAlongX(100);
        assertTrue(device.getCumulativeBuffer().isEmpty());
        assertEquals(1, device.getCurrentBuffer().size());
    }

    @Test
    void aNegativeSizeIsRejectedNamingTheValueAndTheRule() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> device.setCurrentBufferSize(-1));
        assertEquals("-1 was supplied for currentBufferSize: a buffer size must be 0 or more", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> device.setCumulativeBufferSize(-2));
    }

    @Test
    void clearingOneBufferLeavesTheOther() {
        addAlongX(100, 200);
        device.clearCurrentReadings();
        assertTrue(device.getCurrentBuffer().isEmpty());
        assertEquals(2, device.getCumulativeBuffer().size());
        device.clearCumulativeReadings();
        assertTrue(device.getCumulativeBuffer().isEmpty());
    }

    @Test
    void theBuffersAreCopies() {
        addAlongX(100);
        device.getCurrentBuffer().get(0).setX(999);
        assertEquals(100, device.getCurrentBuffer().get(0).getX(), 1e-9);
    }

    @Test
    void addRangeDeviceSetsTheRobotAndRemRangeDeviceClearsIt() {
        ArRangeDevice other = new ArRangeDevice("other", 1000);
        assertNull(other.getRobot());
        robot.addRangeDevice(other);
        assertSame(robot, other.getRobot());
        assertSame(other, robot.findRangeDevice("other"));
        robot.remRangeDevice(other);
        assertNull(other.getRobot());
        assertNull(robot.findRangeDevice("other"));
    }

    @Test
    void aMaxRangeOfZeroIsRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> device.setMaxRange(0));
        assertTrue(e.getMessage().startsWith("0.0 was supplied for maxRange"), e.getMessage());
    }
}
