package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.RobotState;
import robosim.params.ParameterFileReader;
import robosim.protocol.RobotStates;

/** ARIA's angle-interval rule for getClosestSonarRange / getClosestSonarNumber, on a p3dx. */
class ClosestSonarTest {
    private ArRobot robot;

    static Path p3dxFile() {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        return p.resolve("testLoadFiles/robots/p3dx.p");
    }

    @BeforeEach
    void robotWithReadings() {
        robot = new ArRobot("r", "127.0.0.1", 5000, ParameterFileReader.read(p3dxFile()));
        // sonar i reads 1000 + 100·i, except where a test says otherwise
        give(new int[] {1000, 1100, 1200, 1300, 1400, 1500, 1600, 1700,
                1800, 1900, 2000, 2100, 2200, 2300, 2400, 2500});
    }

    private void give(int[] ranges) {
        robot.responded(new RobotSensorResponse(RobotStates.of(1, 100, 0, 0, 0, 0, 0, 0, 0, false, ranges, 0)));
    }

    @Test
    void minusTenToTenExcludesTheSonarsAtPlusAndMinusTen() {
        assertEquals(-1, robot.getClosestSonarNumber(-10, 10));
        assertEquals(-1, robot.getClosestSonarRange(-10, 10));
    }

    @Test
    void slightlyWiderThanTenIncludesThem() {
        assertEquals(3, robot.getClosestSonarNumber(-11, 11));
        assertEquals(1300, robot.getClosestSonarRange(-11, 11));
    }

    @Test
    void twentyToMinusTwentyWrapsThroughTheBack() {
        // the interval runs from 20° counter-clockwise through 180° to −20°: every sonar but 3 and 4
        give(new int[] {900, 900, 900, 500, 400, 900, 900, 900, 900, 900, 900, 700, 900, 900, 900, 900});
        assertEquals(11, robot.getClosestSonarNumber(20, -20));
        assertEquals(700, robot.getClosestSonarRange(20, -20));
        assertEquals(4, robot.getClosestSonarNumber(-20, 20), "the other way round is the front");
    }

    @Test
    void equalBoundsMatchNothing() {
        assertEquals(-1, robot.getClosestSonarNumber(30, 30));
        assertEquals(-1, robot.getClosestSonarRange(0, 0));
        assertEquals(-1, robot.getClosestSonarRange(180, -180), "both normalise to 180");
    }

    @Test
    void tiesGoToTheLowestIndex() {
        give(new int[] {800, 800, 800, 800, 800, 800, 800, 800, 800, 800, 800, 800, 800, 800, 800, 800});
        assertEquals(0, robot.getClosestSonarNumber(-180, 179));
        assertEquals(7, robot.getClosestSonarNumber(-100, -80), "sonars 7 and 8 both face -90");
    }

    @Test
    void boundsAreNormalisedFirst() {
        assertEquals(robot.getClosestSonarNumber(20, -20), robot.getClosestSonarNumber(380, 340));
    }

    @Test
    void sonarCountAndRangesFollowTheParameterFile() {
        assertEquals(16, robot.getNumSonar());
        assertEquals(1500, robot.getSonarRange(5));
        assertEquals(-1, robot.getSonarRange(16));
        assertEquals(-1, robot.getSonarRange(-1));
    }

    @Test
    void aSonarThatNeverReportedReadsTheMaximum() {
        ArRobot fresh = new ArRobot("r", "127.0.0.1", 5000, ParameterFileReader.read(p3dxFile()));
        assertEquals(5000, fresh.getSonarRange(0));
    }

    @Test
    void angleBetweenFollowsTheRule() {
        assertTrue(ArMath.angleBetween(0, -10, 10));
        assertFalse(ArMath.angleBetween(10, -10, 10));
        assertTrue(ArMath.angleBetween(180, 20, -20));
        assertTrue(ArMath.angleBetween(-170, 20, -20));
        assertFalse(ArMath.angleBetween(0, 20, -20));
        assertFalse(ArMath.angleBetween(5, 5, 5));
    }
}
