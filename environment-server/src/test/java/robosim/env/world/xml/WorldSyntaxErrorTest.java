package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Errors in the XML itself and in the attributes of {@code <world>}. */
class WorldSyntaxErrorTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    @Test
    void malformedXmlNamesTheLineOfTheError() {
        fixtures.fails("broken.xml", """
                <world name="broken" width="6000" height="6000">
                  <wall x1="0" y1="0" x2="100" y2="0"/>

                  <wall x1="0" y1=0 x2="100" y2="0"/>
                </world>
                """, 4, "malformed XML", "'0'");
    }

    @Test
    void emptyFileIsMalformed() {
        fixtures.fails("empty.xml", "", 1, "malformed XML");
    }

    @Test
    void missingFileIsNamed() {
        Path file = dir.resolve("environment/nowhere.xml");
        WorldFileException e = assertThrows(WorldFileException.class, () -> WorldReader.read(file));
        assertEquals(file + ": no such world file", e.getMessage());
    }

    @Test
    void rootMustBeWorld() {
        fixtures.fails("root.xml", """
                <?xml version="1.0"?>
                <wrld name="root" width="6000" height="6000"/>
                """, 2, "root element is <wrld>, expected <world>");
    }

    @Test
    void unknownElementIsNamedWithItsParent() {
        fixtures.fails("small.xml", """
                <world name="small" width="6000" height="6000">
                  <wall x1="0" y1="0" x2="100" y2="0"/>



                  <wall x1="0" y1="0" x2="100" y2="0"/>
                  <wal x1="0" y1="0" x2="100" y2="0"/>
                </world>
                """, 7, "unknown element <wal> in <world>");
    }

    @Test
    void unknownChildOfAnElement() {
        fixtures.fails("child.xml", """
                <world name="child" width="6000" height="6000">
                  <polygon points="0,0 100,0 0,100">
                    <point x="1" y="2"/>
                  </polygon>
                </world>
                """, 3, "unknown element <point> in <polygon>");
    }

    @Test
    void unknownAttributeIsNamedOnTheElementsLine() {
        fixtures.fails("attr.xml", """
                <world name="attr" width="6000" height="6000">
                  <wall x1="0" y1="0"
                        x2="100" y2="0" colour="red"/>
                </world>
                """, 2, "unknown attribute colour on <wall>");
    }

    @Test
    void unknownAttributeOnWorld() {
        fixtures.fails("wattr.xml", """
                <world name="wattr" width="6000" height="6000" seed="3">
                </world>
                """, 1, "unknown attribute seed on <world>");
    }

    @Test
    void attributeWrittenAsAnElementIsRefused() {
        fixtures.fails("aselement.xml", """
                <world name="aselement" width="6000" height="6000">
                  <wall x1="0" y1="0" y2="0">
                    <x2>100</x2>
                  </wall>
                </world>
                """, 3, "unknown element <x2> in <wall>", "x2 is an attribute");
    }

    @Test
    void elementWrittenAsAnAttributeIsRefused() {
        fixtures.fails("asattr.xml", """
                <world name="asattr" width="6000" height="6000" wall="1">
                </world>
                """, 1, "unknown attribute wall on <world>", "<wall> is an element");
    }

    @Test
    void strayTextIsRefused() {
        fixtures.fails("text.xml", """
                <world name="text" width="6000" height="6000">
                  <wall x1="0" y1="0" x2="100" y2="0">thick</wall>
                </world>
                """, 2, "unexpected text in <wall>");
    }

    @Test
    void missingRequiredAttributeIsNamed() {
        fixtures.fails("missing.xml", """
                <world name="missing" width="6000" height="6000">
                  <wall x1="0" y1="0" x2="100" y2="0"/>
                  <wall x1="0" y1="0" y2="0"/>
                </world>
                """, 3, "missing required attribute x2 on <wall>");
    }

    @Test
    void emptyElementIsMissingItsAttributesOnItsOwnLine() {
        fixtures.fails("bare.xml", """
                <world name="bare" width="6000" height="6000">

                  <wall/>
                </world>
                """, 3, "missing required attribute x1 on <wall>");
    }

    @ParameterizedTest
    @CsvSource({"name", "width", "height"})
    void worldNeedsNameAndSize(String attribute) {
        String all = "name=\"w\" width=\"6000\" height=\"6000\"";
        String xml = "<world " + all.replaceAll(attribute + "=\"[^\"]*\"", "") + "/>\n";
        fixtures.fails("world.xml", xml, 1, "missing required attribute " + attribute + " on <world>");
    }

    @Test
    void nonNumericValueIsQuoted() {
        fixtures.fails("nan.xml", """
                <world name="nan" width="6000" height="6000">
                  <robot name="r1" type="pioneer" x="1000" y="ten" params="../robots/p3dx.p"/>
                </world>
                """, 2, "attribute y on <robot> is 'ten', not a number");
    }

    @Test
    void nonNumericPointInPolygon() {
        fixtures.fails("points.xml", """
                <world name="points" width="6000" height="6000">
                  <polygon points="0,0 100,0 0,1O0"/>
                </world>
                """, 2, "attribute points on <polygon> is '1O0', not a number");
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "width=\"0\" height=\"6000\"                 | attribute width on <world> is 0 but must be greater than 0",
        "width=\"6000\" height=\"-5\"                | attribute height on <world> is -5 but must be greater than 0",
        "width=\"6000\" height=\"6000\" stepMs=\"0\"     | stepMs on <world> is 0 but must be a whole number from 1 to 10000",
        "width=\"6000\" height=\"6000\" stepMs=\"12.5\"  | stepMs on <world> is 12.5 but must be a whole number",
        "width=\"6000\" height=\"6000\" boundary=\"yes\" | boundary on <world> is 'yes' but must be true or false"})
    void worldAttributesAreChecked(String attributes, String rule) {
        fixtures.fails("size.xml", "<world name=\"size\" " + attributes + ">\n</world>\n", 1, rule);
    }

    @Test
    void messageStartsWithTheFilePath() {
        WorldFileException e = fixtures.fails("path.xml", "<world name=\"p\" width=\"x\" height=\"1\"/>\n", 1);
        assertTrue(e.getMessage().startsWith(dir.resolve("environment/path.xml") + ":1: "), e.getMessage());
        assertEquals("attribute width on <world> is 'x', not a number", e.rule());
    }
}
