package robosim.params;

import robosim.protocol.RobotParameters;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The rules the XML form shares with the {@code .p} form, one broken file each: the message
 * names the file, the line of the offending element and the rule, in the XML form's spelling.
 */
class XmlParameterFileRulesTest {
    @TempDir
    Path dir;

    /** Writes a file whose first line is the root's start tag, so the body starts at line 2. */
    private Path write(String name, String body) throws IOException {
        return Files.writeString(dir.resolve(name), "<robotParameters>\n" + body + "</robotParameters>\n",
                StandardCharsets.UTF_8);
    }

    private static void assertRejected(Path file, int line, String rule) {
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> XmlParameterFileReader.read(file));
        assertEquals(file + ":" + line + ": " + rule, e.getMessage());
    }

    @Test
    void nonNumericValueIsRejected() throws IOException {
        Path file = write("word.xml", """
                  <robotRadius>250</robotRadius>
                  <maxVelocity>fast</maxVelocity>
                """);

        assertRejected(file, 3, "maxVelocity 'fast' is not a number");
    }

    @Test
    void emptyValueIsRejected() throws IOException {
        Path file = write("novalue.xml", """
                  <subclass/>
                """);

        assertRejected(file, 2, "subclass has no value");
    }

    @Test
    void negativeRobotWidthIsRejected() throws IOException {
        Path file = write("width.xml", """
                  <robotWidth>-425</robotWidth>
                """);

        assertRejected(file, 2, "robotWidth is -425 but must be greater than 0");
    }

    @Test
    void zeroMaxVelocityIsRejected() throws IOException {
        Path file = write("still.xml", """
                  <class>Pioneer</class>
                  <maxVelocity>0</maxVelocity>
                """);

        assertRejected(file, 3, "maxVelocity is 0 but must be greater than 0");
    }

    @Test
    void negativeRobotLengthIsRejected() throws IOException {
        Path file = write("length.xml", """
                  <robotLength>-511</robotLength>
                """);

        assertRejected(file, 2, "robotLength is -511 but must not be negative");
    }

    @Test
    void lengthWithoutFrontAndRearIsSplitEvenly() throws IOException {
        Path file = write("even.xml", """
                  <robotLength>600</robotLength>
                """);

        RobotParameters p = XmlParameterFileReader.read(file);

        assertEquals(300, p.robotLengthFront());
        assertEquals(300, p.robotLengthRear());
    }

    @Test
    void nonNumericLaserAttributeIsRejected() throws IOException {
        Path file = write("laserword.xml", """
                  <laser x="front" y="0" th="0"/>
                """);

        assertRejected(file, 2, "laser x 'front' is not a number");
    }

    @Test
    void negativeLaserMaxRangeIsRejected() throws IOException {
        Path file = write("laserrange.xml", """
                  <laser x="18" y="0" th="0" maxRange="-8000"/>
                """);

        assertRejected(file, 2, "laser maxRange is -8000 but must not be negative");
    }

    @Test
    void laserMaxRangeZeroMeansTheDefaultAsInThePForm() throws IOException {
        Path file = write("laserzero.xml", """
                  <laser x="18" y="0" th="0" maxRange="0"/>
                """);

        assertEquals(RobotParameters.DEFAULT_LASER_MAX_RANGE, XmlParameterFileReader.read(file).laserMaxRange());
    }

    @Test
    void fractionalSonarNumIsRejected() throws IOException {
        Path file = write("half.xml", """
                  <sonarNum>2.5</sonarNum>
                """);

        assertRejected(file, 2, "sonarNum 2.5 must be a whole number from 0 to 32");
    }

    @Test
    void sonarNumAboveTheMostSonarsIsRejected() throws IOException {
        Path file = write("many.xml", """
                  <sonarNum>1000000</sonarNum>
                """);

        assertRejected(file, 2, "sonarNum 1000000 must be a whole number from 0 to 32");
    }

    @Test
    void sonarUnitWithoutAnAttributeIsRejected() throws IOException {
        Path file = write("short.xml", """
                  <sonarNum>1</sonarNum>
                  <sonarUnit number="0" x="69" y="136"/>
                """);

        assertRejected(file, 3, "sonarUnit has no attribute th (it needs number, x, y and th)");
    }

    @Test
    void nonNumericSonarCoordinateIsRejected() throws IOException {
        Path file = write("sonarword.xml", """
                  <sonarNum>1</sonarNum>
                  <sonarUnit number="0" x="69" y="left" th="90"/>
                """);

        assertRejected(file, 3, "sonarUnit y 'left' is not a number");
    }

    @Test
    void negativeSonarNumberIsRejected() throws IOException {
        Path file = write("negnumber.xml", """
                  <sonarUnit number="-1" x="69" y="136" th="90"/>
                """);

        assertRejected(file, 2, "sonarUnit number -1 must be a whole number from 0");
    }

    @Test
    void sonarNumberNotBelowSonarNumIsRejected() throws IOException {
        StringBuilder units = new StringBuilder("  <sonarNum>16</sonarNum>\n");
        for (int n = 0; n <= 16; n++) {
            units.append("  <sonarUnit number=\"").append(n).append("\" x=\"0\" y=\"0\" th=\"0\"/>\n");
        }
        Path file = write("p3dx.xml", units.toString());

        assertRejected(file, 19, "sonarUnit number 16 must be less than sonarNum 16");
    }

    @Test
    void sonarNumberBeyondALaterSonarNumIsRejectedAtTheSonarUnit() throws IOException {
        Path file = write("late.xml", """
                  <sonarUnit number="0" x="69" y="136" th="90"/>
                  <sonarUnit number="5" x="148" y="78" th="30"/>
                  <sonarNum>1</sonarNum>
                """);

        assertRejected(file, 3, "sonarUnit number 5 must be less than sonarNum 1");
    }

    @Test
    void duplicateSonarUnitIsRejected() throws IOException {
        Path file = write("twice.xml", """
                  <sonarNum>2</sonarNum>
                  <sonarUnit number="0" x="69" y="136" th="90"/>
                  <sonarUnit number="1" x="114" y="119" th="50"/>
                  <sonarUnit number="1" x="148" y="78" th="30"/>
                """);

        assertRejected(file, 5, "sonarUnit 1 is given twice");
    }

    @Test
    void missingSonarUnitIsRejectedAtTheSonarNumLine() throws IOException {
        Path file = write("gap.xml", """
                  <sonarNum>3</sonarNum>
                  <sonarUnit number="0" x="69" y="136" th="90"/>
                  <sonarUnit number="2" x="148" y="78" th="30"/>
                """);

        assertRejected(file, 2, "sonarNum is 3 but there is no sonarUnit 1");
    }

    @Test
    void missingSonarUnitWithoutSonarNumNamesTheFile() throws IOException {
        Path file = write("gapnonum.xml", """
                  <sonarUnit number="1" x="114" y="119" th="50"/>
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> XmlParameterFileReader.read(file));

        assertEquals(file + ": sonarNum is 1 but there is no sonarUnit 0", e.getMessage());
    }
}
