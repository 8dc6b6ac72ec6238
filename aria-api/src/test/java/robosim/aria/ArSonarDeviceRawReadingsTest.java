package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** The sonar device's raw readings: copies of the sonar readings new in the latest cycle. */
class ArSonarDeviceRawReadingsTest {
    @Test
    void theRawReadingsAreThisCyclesNewSonarReadings() {
        ArRobot robot = Cycles.p3dxRobot();
        ArSonarDevice sonar = new ArSonarDevice();
        robot.addRangeDevice(sonar);
        int[] ranges = new int[16];
        Arrays.fill(ranges, 1500);
        ranges[4] = 700;
        Cycles.cycle(robot, 100, 0, 0, 0, ranges, new int[0]);
        assertEquals(16, sonar.getRawReadings().size());
        assertEquals(700, sonar.getRawReadings().get(4).getRange());
        assertNotSame(robot.getSonarReading(4), sonar.getRawReadings().get(4));
        Cycles.cycle(robot, 200, 0, 0, 0);
        assertTrue(sonar.getRawReadings().isEmpty(), "no sonar reported in this cycle");
    }

    @Test
    void aPlainRangeDeviceHasNoRawReadings() {
        assertTrue(new ArRangeDevice("plain", 1000).getRawReadings().isEmpty());
    }
}
