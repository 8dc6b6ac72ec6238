package robosim.env.world.xml;

import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Walls and polygons whose geometry is degenerate. */
class WorldGeometryErrorTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    private void failsWith(String element, String... words) {
        fixtures.fails("geometry.xml", """
                <world name="geometry" width="6000" height="6000">
                  <polygon points="3000,3000 3500,3000 3000,3500"/>
                  %s
                </world>
                """.formatted(element), 3, words);
    }

    @Test
    void aWorldWiderThanAHundredKilometresIsRefused() {
        fixtures.fails("huge.xml", """
                <world name="huge" width="2e8" height="6000">
                </world>
                """, 1, "attribute width on <world> is", "but must be at most 100000000");
    }

    @Test
    void coordinatesFarOutsideAnyWorldAreRefusedBeforeTheyReachTheGeometry() {
        failsWith("<polygon points=\"100,100 200,100 200,1e308\"/>", "attribute points on <polygon> is 1e308 but must"
                + " be from -1000000000 to 1000000000: no number in a world file is larger");
        failsWith("<wall x1=\"0\" y1=\"0\" x2=\"-4e9\" y2=\"5\"/>", "attribute x2 on <wall> is -4e9 but must be from");
    }

    @Test
    void aRobotWhoseParameterFileBreaksAPhysicalBoundIsRefusedNamingTheFile() {
        fixtures.writeRobot("fast.p", "ConfigVersion 2.0\nSection General settings\nClass Pioneer\nSubclass p3dx\n"
                + "MaxVelocity 1e300\n");
        fixtures.fails("fast.xml", """
                <world name="fast" width="6000" height="6000">
                  <robot name="r1" type="pioneer" x="1000" y="1000" params="../robots/fast.p"/>
                </world>
                """, 2, "robot 'r1': parameter file ../robots/fast.p breaks a bound: 1.0E300 was supplied for maxVelocity");
    }

    @Test
    void aRobotNameOutsideTheNameRuleIsRefused() {
        fixtures.fails("names.xml", """
                <world name="names" width="6000" height="6000">
                  <robot name="r 1" type="pioneer" x="1000" y="1000" params="p3dx.p"/>
                </world>
                """, 2, "a robot's name is 1 to 64 letters", "'r 1' is not");
    }

    @Test
    void polygonWithTwoDistinctPoints() {
        failsWith("<polygon points=\"0,0 100,100 100,100 0,0\"/>", "polygon has 2 distinct points but needs at least 3");
    }

    @Test
    void polygonWithOddNumberOfCoordinates() {
        failsWith("<polygon points=\"0,0 100,0 100\"/>", "points on <polygon> has 5 numbers; it needs x,y pairs");
    }

    @Test
    void polygonWithZeroArea() {
        failsWith("<polygon points=\"0,0 100,100 200,200\"/>", "polygon has zero area");
    }

    @Test
    void selfIntersectingPolygon() {
        failsWith("<polygon points=\"0,0 1000,1000 1000,0 0,1000\"/>", "polygon is self-intersecting at (500, 500)");
    }

    @Test
    void polygonTouchingItselfAtAPoint() {
        failsWith("<polygon points=\"0,0 1000,0 500,500 1000,1000 0,1000 500,500\"/>",
                "polygon is self-intersecting at (500, 500)");
    }

    @Test
    void polygonHeightMustBePositive() {
        failsWith("<polygon points=\"0,0 100,0 0,100\" height=\"0\"/>",
                "attribute height on <polygon> is 0 but must be greater than 0");
    }

    @Test
    void wallOfZeroLength() {
        failsWith("<wall x1=\"100\" y1=\"200\" x2=\"100\" y2=\"200\"/>", "wall from (100, 200) to (100, 200) has zero length");
    }

    @Test
    void wallThicknessMustBePositive() {
        failsWith("<wall x1=\"0\" y1=\"0\" x2=\"100\" y2=\"0\" thickness=\"0\"/>",
                "attribute thickness on <wall> is 0 but must be greater than 0");
    }

    @Test
    void negativeWallThickness() {
        failsWith("<wall x1=\"0\" y1=\"0\" x2=\"100\" y2=\"0\" thickness=\"-10\"/>",
                "attribute thickness on <wall> is -10 but must be greater than 0");
    }

    /** A point this far out made the reader's geometry grid infinitely large: it failed with an ArrayIndexOutOfBoundsException. */
    @Test
    void aPolygonPointBeyondAHundredKilometresIsRefused() {
        failsWith("<polygon points=\"0,0 100,0 -5e8,100\"/>",
                "attribute points on <polygon> holds -500000000 but a coordinate must be from -100000000 to 100000000");
    }

    @Test
    void aWallEndBeyondAHundredKilometresIsRefused() {
        failsWith("<wall x1=\"0\" y1=\"0\" x2=\"100\" y2=\"1e9\"/>",
                "attribute y2 on <wall> holds 1000000000 but a coordinate must be from -100000000 to 100000000");
    }

    @Test
    void aWallThickerThanAHundredKilometresIsRefused() {
        failsWith("<wall x1=\"0\" y1=\"0\" x2=\"100\" y2=\"0\" thickness=\"2e8\"/>",
                "attribute thickness on <wall> is 200000000 but must be at most 100000000");
    }
}
