package robosim.params;

import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Reading the XML form, and the errors that belong to XML itself. */
class XmlParameterFileReaderTest {
    @TempDir
    Path dir;

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.UTF_8);
    }

    private static void assertRejected(Path file, int line, String rule) {
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> XmlParameterFileReader.read(file));
        assertEquals(file + ":" + line + ": " + rule, e.getMessage());
    }

    // --- reading ---

    @Test
    void absentElementsKeepTheDefaultsOfThePForm() throws IOException {
        Path xml = write("bare.xml", "<robotParameters/>\n");
        Path p = write("bare.p", "ConfigVersion 2.0\n");

        assertEquals(ParameterFileReader.read(p), XmlParameterFileReader.read(xml));
    }

    @Test
    void everyRepeatedSonarUnitIsKeptInNumberOrder() throws IOException {
        Path file = write("three.xml", """
                <robotParameters>
                  <sonarUnit number="2" x="148" y="78" th="30"/>
                  <sonarUnit number="0" x="69" y="136" th="90"/>
                  <sonarNum>3</sonarNum>
                  <sonarUnit number="1" x="114" y="119" th="50"/>
                </robotParameters>
                """);

        assertEquals(List.of(new SonarUnit(0, 69, 136, 90), new SonarUnit(1, 114, 119, 50),
                new SonarUnit(2, 148, 78, 30)), XmlParameterFileReader.read(file).sonarUnits());
    }

    @Test
    void sonarUnitsBetweenOtherElementsAreAllKept() throws IOException {
        Path file = write("mixed.xml", """
                <robotParameters>
                  <sonarUnit number="0" x="1" y="2" th="3"/>
                  <robotWidth>425</robotWidth>
                  <sonarUnit number="1" x="4" y="5" th="6"/>
                </robotParameters>
                """);

        assertEquals(2, XmlParameterFileReader.read(file).sonarUnits().size());
    }

    @Test
    void laserAttributesGiveTheMountingPoseAndRange() throws IOException {
        Path file = write("laser.xml", """
                <robotParameters>
                  <laser x="18" y="-5" th="180" maxRange="32000"/>
                </robotParameters>
                """);

        RobotParameters p = XmlParameterFileReader.read(file);

        assertEquals(List.of(18.0, -5.0, 180.0, 32000.0),
                List.of(p.laserX(), p.laserY(), p.laserTh(), p.laserMaxRange()));
    }

    @Test
    void laserWithoutMaxRangeKeepsTheDefaultRange() throws IOException {
        Path file = write("laserpose.xml", """
                <robotParameters>
                  <laser x="160" y="0" th="0"/>
                </robotParameters>
                """);

        assertEquals(RobotParameters.DEFAULT_LASER_MAX_RANGE, XmlParameterFileReader.read(file).laserMaxRange());
    }

    @Test
    void whitespaceAndCommentsAroundValuesAreIgnored() throws IOException {
        Path file = write("spaced.xml", """
                <?xml version="1.0" encoding="UTF-8"?>
                <!-- a robot -->
                <robotParameters>
                  <robotWidth>
                    425 <!-- mm -->
                  </robotWidth>
                  <subclass> custom </subclass>
                </robotParameters>
                """);

        RobotParameters p = XmlParameterFileReader.read(file);

        assertEquals(List.of("425.0", "custom"), List.of(String.valueOf(p.robotWidth()), p.subclass()));
    }

    @Test
    void subclassDefaultsToTheFileName() throws IOException {
        Path file = write("myrobot.xml", "<robotParameters></robotParameters>");

        assertEquals("myrobot", XmlParameterFileReader.read(file).subclass());
    }

    @Test
    void missingFileIsAnUncheckedIoErrorNamingIt() {
        Path file = dir.resolve("absent.xml");

        UncheckedIOException e = assertThrows(UncheckedIOException.class, () -> XmlParameterFileReader.read(file));

        assertEquals("cannot read robot parameter file " + file, e.getMessage());
    }

    // --- XML-level errors name the file, the line and the rule ---

    @Test
    void malformedXmlGivesTheParsersLine() throws IOException {
        Path file = write("broken.xml", """
                <robotParameters>
                  <robotWidth>425</robotWidth>
                  <robotRadius>250</robotWidth>
                </robotParameters>
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> XmlParameterFileReader.read(file));

        assertTrue(e.getMessage().startsWith(file + ":3: malformed XML: "), e.getMessage());
    }

    @Test
    void secondRootElementIsMalformed() throws IOException {
        Path file = write("tworoots.xml", """
                <robotParameters>
                  <robotWidth>425</robotWidth>
                </robotParameters>
                <robotParameters/>
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> XmlParameterFileReader.read(file));

        assertTrue(e.getMessage().startsWith(file + ":4: malformed XML: "), e.getMessage());
    }

    @Test
    void emptyFileIsMalformed() throws IOException {
        Path file = write("empty.xml", "");

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> XmlParameterFileReader.read(file));

        assertTrue(e.getMessage().startsWith(file + ":1: malformed XML: "), e.getMessage());
    }

    @Test
    void externalEntitiesAreNotRead() throws IOException {
        Path secret = write("secret.txt", "42");
        Path file = write("entity.xml", """
                <?xml version="1.0"?>
                <!DOCTYPE robotParameters [ <!ENTITY width SYSTEM "%s"> ]>
                <robotParameters>
                  <robotWidth>&width;</robotWidth>
                </robotParameters>
                """.formatted(secret.toUri()));

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> XmlParameterFileReader.read(file));

        assertTrue(e.getMessage().startsWith(file + ":4: malformed XML: "), e.getMessage());
    }

    @Test
    void otherRootElementIsRejected() throws IOException {
        Path file = write("world.xml", """
                <?xml version="1.0"?>

                <world width="10" height="10"/>
                """);

        assertRejected(file, 3, "the root element is <world>, expected <robotParameters> or <robot>");
    }

    @Test
    void unknownElementIsRejectedAtItsLine() throws IOException {
        Path file = write("unknown.xml", """
                <robotParameters>
                  <robotWidth>425</robotWidth>
                  <wheelCount>2</wheelCount>
                </robotParameters>
                """);

        assertRejected(file, 3, "unknown element <wheelCount> in <robotParameters>");
    }

    @Test
    void elementNamesAreMatchedExactly() throws IOException {
        Path file = write("case.xml", """
                <robotParameters>
                  <RobotWidth>425</RobotWidth>
                </robotParameters>
                """);

        assertRejected(file, 2, "unknown element <RobotWidth> in <robotParameters>");
    }

    @Test
    void attributeOnTheRootIsRejected() throws IOException {
        Path file = write("version.xml", """
                <robotParameters
                    version="2">
                </robotParameters>
                """);

        assertRejected(file, 1, "unknown attribute version on <robotParameters>");
    }

    @Test
    void unknownAttributeOnSonarUnitIsRejectedAtItsLine() throws IOException {
        Path file = write("sonarattr.xml", """
                <robotParameters>
                  <sonarNum>1</sonarNum>
                  <sonarUnit number="0" x="69" y="136" th="90" z="200"/>
                </robotParameters>
                """);

        assertRejected(file, 3, "unknown attribute z on <sonarUnit> (known: number, x, y, th)");
    }

    @Test
    void unknownAttributeOnLaserIsRejected() throws IOException {
        Path file = write("laserattr.xml", """
                <robotParameters>
                  <laser x="18" y="0" th="0" flipped="true"/>
                </robotParameters>
                """);

        assertRejected(file, 2, "unknown attribute flipped on <laser> (known: x, y, th, maxRange)");
    }

    @Test
    void attributeOnAValueElementIsRejected() throws IOException {
        Path file = write("unit.xml", """
                <robotParameters>
                  <class>Pioneer</class>
                  <robotWidth unit="mm">425</robotWidth>
                </robotParameters>
                """);

        assertRejected(file, 3, "unknown attribute unit on <robotWidth>");
    }

    @Test
    void elementInsideAValueElementIsRejectedAtItsLine() throws IOException {
        Path file = write("nested.xml", """
                <robotParameters>
                  <robotWidth>
                    <mm>425</mm>
                  </robotWidth>
                </robotParameters>
                """);

        assertRejected(file, 3, "unknown element <mm> in <robotWidth>");
    }

    @Test
    void elementInsideSonarUnitIsRejectedAtItsLine() throws IOException {
        Path file = write("sonarchild.xml", """
                <robotParameters>
                  <sonarUnit number="0" x="69" y="136" th="90">
                    <range>5000</range>
                  </sonarUnit>
                </robotParameters>
                """);

        assertRejected(file, 3, "unknown element <range> in <sonarUnit>");
    }

    @Test
    void textInsideSonarUnitIsRejected() throws IOException {
        Path file = write("sonartext.xml", """
                <robotParameters>
                  <sonarUnit>0 69 136 90</sonarUnit>
                </robotParameters>
                """);

        assertRejected(file, 2, "<sonarUnit> takes attributes, not text '0 69 136 90'");
    }

    @Test
    void textDirectlyInTheRootIsRejected() throws IOException {
        Path file = write("roottext.xml", """
                <robotParameters>
                  <robotWidth>425</robotWidth>
                  RobotRadius 250
                </robotParameters>
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> XmlParameterFileReader.read(file));

        assertTrue(e.getMessage().endsWith(": text 'RobotRadius 250' in <robotParameters>: parameters are child elements"),
                e.getMessage());
    }

    @Test
    void elementGivenTwiceIsRejectedNamingBothLines() throws IOException {
        Path file = write("twice.xml", """
                <robotParameters>
                  <maxVelocity>2200</maxVelocity>
                  <robotWidth>425</robotWidth>
                  <maxVelocity>1200</maxVelocity>
                </robotParameters>
                """);

        assertRejected(file, 4, "<maxVelocity> is given twice (first at line 2)");
    }

    @Test
    void laserGivenTwiceIsRejected() throws IOException {
        Path file = write("twolasers.xml", """
                <robotParameters>
                  <laser x="18" y="0" th="0"/>
                  <laser x="-200" y="0" th="180"/>
                </robotParameters>
                """);

        assertRejected(file, 3, "<laser> is given twice (first at line 2)");
    }
}
