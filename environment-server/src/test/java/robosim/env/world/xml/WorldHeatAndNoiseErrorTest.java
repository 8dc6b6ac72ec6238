package robosim.env.world.xml;

import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Heat sources and noise that break a rule of the format. */
class WorldHeatAndNoiseErrorTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    /** Fails with the element on line 4, after a polygon on line 2 and a valid heat source. */
    private void failsWith(String element, String... words) {
        fixtures.fails("w.xml", """
                <world name="w" width="8000" height="8000">
                  <polygon points="2000,2000 2600,2000 2600,2600 2000,2600"/>
                  <heat x="7000" y="3000" intensity="40"/>
                  %s
                </world>
                """.formatted(element), 4, words);
    }

    @Test
    void heatNeedsX() {
        failsWith("<heat y=\"100\" intensity=\"40\"/>", "missing required attribute x on <heat>");
    }

    @Test
    void heatNeedsY() {
        failsWith("<heat x=\"100\" intensity=\"40\"/>", "missing required attribute y on <heat>");
    }

    @Test
    void heatNeedsIntensity() {
        failsWith("<heat x=\"100\" y=\"100\"/>", "missing required attribute intensity on <heat>");
    }

    @Test
    void heatCoordinatesAreNumbers() {
        failsWith("<heat x=\"100\" y=\"north\" intensity=\"40\"/>", "attribute y on <heat> is 'north', not a number");
    }

    @ParameterizedTest
    @CsvSource({"0", "-5"})
    void heatIntensityMustBePositive(String intensity) {
        failsWith("<heat x=\"100\" y=\"100\" intensity=\"" + intensity + "\"/>",
                "attribute intensity on <heat> is " + intensity + " but must be greater than 0");
    }

    @ParameterizedTest
    @CsvSource({"9000, 100", "-1, 100", "100, 8000.5", "100, -0.5"})
    void heatOutsideTheWorld(String x, String y) {
        failsWith("<heat x=\"" + x + "\" y=\"" + y + "\" intensity=\"40\"/>",
                "heat source at (" + x + ", " + y + ") is outside the world 8000 x 8000");
    }

    @Test
    void heatInsideAPolygon() {
        failsWith("<heat x=\"2300\" y=\"2300\" intensity=\"40\"/>", "heat source at (2300, 2300) is inside the polygon at line 2");
    }

    @Test
    void heatInsideAWallListedAfterIt() {
        fixtures.fails("later.xml", """
                <world name="later" width="8000" height="8000">
                  <heat x="1000" y="3020" intensity="40"/>
                  <wall x1="0" y1="3000" x2="2000" y2="3000"/>
                </world>
                """, 2, "heat source at (1000, 3020) is inside the wall at line 3");
    }

    @Test
    void heatInsideABoundaryWall() {
        fixtures.fails("boundary.xml", """
                <world name="boundary" width="8000" height="8000" boundary="true">
                  <heat x="7950" y="3000" intensity="40"/>
                </world>
                """, 2, "heat source at (7950, 3000) is inside a boundary wall");
    }

    @Test
    void heatTakesOnlyItsAttributes() {
        failsWith("<heat x=\"100\" y=\"100\" intensity=\"40\" radius=\"5\"/>", "unknown attribute radius on <heat>");
    }

    @Test
    void atMostOneNoise() {
        fixtures.fails("w.xml", """
                <world name="w" width="8000" height="8000">
                  <wall x1="0" y1="3000" x2="2000" y2="3000"/>

                  <noise sonar="5"/>
                  <heat x="7000" y="3000" intensity="40"/>
                  <noise laser="5"/>
                </world>
                """, 6, "a world has at most one <noise>; the first is at line 4");
    }

    @ParameterizedTest
    @CsvSource({"sonar, -1", "laser, -0.5", "odometry, -0.0075"})
    void noiseMustNotBeNegative(String attribute, String value) {
        failsWith("<noise " + attribute + "=\"" + value + "\"/>",
                "attribute " + attribute + " on <noise> is " + value + " but must be 0 or greater");
    }

    @Test
    void noiseFiguresAreNumbers() {
        failsWith("<noise odometry=\"0.75%\"/>", "attribute odometry on <noise> is '0.75%', not a number");
    }

    @Test
    void noiseTakesOnlyItsAttributes() {
        failsWith("<noise sonar=\"5\" compass=\"2\"/>", "unknown attribute compass on <noise>");
    }
}
