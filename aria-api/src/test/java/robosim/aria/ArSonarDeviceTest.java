package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** ArSonarDevice: each cycle, only the sonar readings new in that cycle and below its maximum range. */
class ArSonarDeviceTest {
    private ArRobot robot;
    private ArSonarDevice sonar;

    @BeforeEach
    void attached() {
        robot = Cycles.p3dxRobot();
        sonar = new ArSonarDevice();
        robot.addRangeDevice(sonar);
    }

    /** Sonars 3 and 4 (facing ±10°) read 1000 and 1200 mm, sonar 12 (facing 170°) 2000; the rest see nothing. */
    private static int[] threeEchoes() {
        int[] r = new int[16];
        Arrays.fill(r, 5000);
        r[3] = 1000;
        r[4] = 1200;
        r[12] = 2000;
        return r;
    }

    @Test
    void theDefaultsAreArias() {
        assertEquals("sonar", sonar.getName());
        assertEquals(24, sonar.getCurrentBufferSize());
        assertEquals(64, sonar.getCumulativeBufferSize());
        assertEquals(5000, sonar.getMaxRange());
    }

    @Test
    void readingsBelowTheMaximumRangeAreAddedAtTheirGlobalPositions() {
        Cycles.cycle(robot, 100, 500, 200, 30, threeEchoes(), new int[0]);
        List<ArPose> current = sonar.getCurrentBuffer();
        assertEquals(3, current.size(), "the 13 sonars at 5000 mm saw nothing");
        // added in index order, so the newest first is sonar 12's
        int[] order = {12, 4, 3};
        for (int k = 0; k < 3; k++) {
            ArSensorReading r = robot.getSonarReading(order[k]);
            assertEquals(r.getX(), current.get(k).getX(), 1e-9);
            assertEquals(r.getY(), current.get(k).getY(), 1e-9);
        }
    }

    @Test
    void theGlobalPositionIsTheTransducersEcho() {
        // sonar 3 sits at (166, 27) facing 10°; the robot at the origin facing 0
        Cycles.cycle(robot, 100, 0, 0, 0, threeEchoes(), new int[0]);
        ArPose p = sonar.getCurrentBuffer().get(2);
        assertEquals(166 + 1000 * Math.cos(Math.toRadians(10)), p.getX(), 1e-9);
        assertEquals(27 + 1000 * Math.sin(Math.toRadians(10)), p.getY(), 1e-9);
    }

    @Test
    void aCycleWithoutSonarReadingsAddsNothing() {
        Cycles.cycle(robot, 100, 0, 0, 0, threeEchoes(), new int[0]);
        Cycles.cycle(robot, 200, 0, 0, 0, new int[0], new int[0]);
        assertEquals(3, sonar.getCurrentBuffer().size(), "last cycle's readings are not new any more");
    }

    @Test
    void everyCycleWithReadingsAddsThemAgain() {
        Cycles.cycle(robot, 100, 0, 0, 0, threeEchoes(), new int[0]);
        Cycles.cycle(robot, 200, 0, 0, 0, threeEchoes(), new int[0]);
        assertEquals(6, sonar.getCurrentBuffer().size());
        assertEquals(3, sonar.getCumulativeBuffer().size(), "the same echoes merge in the cumulative buffer");
    }

    @Test
    void aLowerMaximumRangeKeepsFartherEchoesOut() {
        sonar.setMaxRange(1200);
        Cycles.cycle(robot, 100, 0, 0, 0, threeEchoes(), new int[0]);
        assertEquals(1, sonar.getCurrentBuffer().size(), "only 1000 is below 1200");
        assertEquals(1200, sonar.currentReadingPolar(-40, -20), "sonar 4's 1200 mm is not below 1200");
    }

    @Test
    void theNearestEchoAheadAnswersThePolarQuery() {
        Cycles.cycle(robot, 100, 0, 0, 0, threeEchoes(), new int[0]);
        double expected = Math.hypot(166 + 1000 * Math.cos(Math.toRadians(10)),
                27 + 1000 * Math.sin(Math.toRadians(10)));
        assertEquals(expected, sonar.currentReadingPolar(-20, 20), 1e-9);
        assertTrue(sonar.currentReadingPolar(160, -160) > 2000, "sonar 12 is behind, 2000 mm from its transducer");
    }

    @Test
    void aRemovedDeviceTakesNoMoreReadings() {
        robot.remRangeDevice(sonar);
        Cycles.cycle(robot, 100, 0, 0, 0, threeEchoes(), new int[0]);
        assertTrue(sonar.getCurrentBuffer().isEmpty());
    }
}
