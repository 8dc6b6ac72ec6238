package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * A range device's readings moved by a rigid motion (ARIA's {@code ArRangeDevice::applyTransform}):
 * the current buffer always, the cumulative one when asked.
 */
class ArRangeDeviceTransformTest {
    private final ArRobot robot = Cycles.p3dxRobot();
    private final ArRangeDevice device = new ArRangeDevice("test", 5000, 5, 5);

    @BeforeEach
    void aReadingAheadOfTheRobot() {
        robot.addRangeDevice(device);
        Cycles.cycle(robot, 100, 0, 0, 0);
        device.addReading(1000, 0);
    }

    private static void assertAt(double x, double y, List<ArPose> buffer) {
        assertEquals(1, buffer.size(), buffer.toString());
        assertEquals(x, buffer.get(0).getX(), 1e-9);
        assertEquals(y, buffer.get(0).getY(), 1e-9);
    }

    @Test
    void bothBuffersMoveWhenTheCumulativeOneIsAskedFor() {
        ArTransform quarterTurn = new ArTransform(new ArPose(0, 0, 0), new ArPose(0, 0, 90));
        device.applyTransform(quarterTurn, true);
        assertAt(0, 1000, device.getCurrentBuffer());
        assertAt(0, 1000, device.getCumulativeBuffer());
    }

    @Test
    void otherwiseOnlyTheCurrentBufferMoves() {
        ArTransform shift = new ArTransform(new ArPose(0, 0, 0), new ArPose(500, -200, 0));
        device.applyTransform(shift, false);
        assertAt(1500, -200, device.getCurrentBuffer());
        assertAt(1000, 0, device.getCumulativeBuffer());
    }

    @Test
    void theBumpersSpanAriasRangeOrTheOneGiven() {
        assertEquals(135, new ArBumpers().getAngleRange());
        assertEquals(90, new ArBumpers(10, 10, "b", 5, 90).getAngleRange());
    }
}
