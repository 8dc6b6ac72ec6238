package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import robosim.env.world.World;
import robosim.env.world.WorldObject;

/** The {@code <object>} element: pucks, their radius and colour, and the rules they break. */
class WorldObjectTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    @Test
    void objectsAreReadInFileOrderWithTheirDefaults() {
        World world = fixtures.read("pucks.xml", """
                <world name="w" width="8000" height="8000">
                  <object type="puck" x="1000" y="2000" color="red"/>
                  <wall x1="0" y1="5000" x2="3000" y2="5000" thickness="100"/>
                  <object x="3000" y="2000" radius="30" color="#00ff00"/>
                </world>
                """);
        List<WorldObject> objects = world.objects();
        assertEquals(2, objects.size());
        assertEquals(new WorldObject("puck", 1000, 2000, WorldObject.DEFAULT_RADIUS, "red", 2), objects.get(0));
        assertEquals(new WorldObject("puck", 3000, 2000, 30, "#00ff00", 4), objects.get(1));
        assertNull(fixtures.read("one.xml", """
                <world name="w" width="8000" height="8000"><object x="100" y="100"/></world>
                """).objects().get(0).color());
    }

    /** Fails with the element on line 4, after a polygon on line 2 and a valid object on line 3. */
    private void failsWith(String element, String... words) {
        fixtures.fails("w.xml", """
                <world name="w" width="8000" height="8000">
                  <polygon points="2000,2000 2600,2000 2600,2600 2000,2600"/>
                  <object x="7000" y="3000"/>
                  %s
                </world>
                """.formatted(element), 4, words);
    }

    @Test
    void anObjectNeedsX() {
        failsWith("<object y=\"100\"/>", "missing required attribute x on <object>");
    }

    @Test
    void anObjectsCoordinatesAreNumbers() {
        failsWith("<object x=\"100\" y=\"north\"/>", "attribute y on <object> is 'north', not a number");
    }

    @Test
    void anUnknownTypeIsRefused() {
        failsWith("<object type=\"ball\" x=\"100\" y=\"100\"/>", "type 'ball' is not a type of object", "'puck'");
    }

    @ParameterizedTest
    @CsvSource({"5", "0", "-3", "150"})
    void theRadiusIsBounded(String radius) {
        failsWith("<object x=\"500\" y=\"500\" radius=\"" + radius + "\"/>", "was supplied for radius",
                "10 to 100 mm");
    }

    @Test
    void aColourIsANameOrHex() {
        failsWith("<object x=\"500\" y=\"500\" color=\"#12\"/>", "'#12' was supplied for color");
    }

    @Test
    void anUnknownAttributeIsRefused() {
        failsWith("<object x=\"500\" y=\"500\" mass=\"3\"/>", "unknown attribute mass on <object>");
    }

    @Test
    void anObjectMustBeWhollyInsideTheWorld() {
        failsWith("<object x=\"20\" y=\"500\"/>", "puck at (20, 500) of radius 38 is not wholly inside the world");
    }

    @Test
    void anObjectMayNotTouchAnObstacle() {
        failsWith("<object x=\"1970\" y=\"2300\"/>", "puck at (1970, 2300) touches the polygon at line 2");
    }

    @Test
    void objectsMayNotTouchEachOther() {
        failsWith("<object x=\"7050\" y=\"3000\"/>", "touches the object at line 3");
    }

    @Test
    void anObjectMayNotTouchARobotAtItsStart() {
        fixtures.fails("w.xml", """
                <world name="w" width="8000" height="8000">
                  <robot name="r" type="pioneer" x="1000" y="1000" th="0" params="../robots/p3dx.p"/>
                  <object x="1230" y="1000"/>
                </world>
                """, 3, "puck at (1230, 1000) touches robot r at its start");
    }
}
