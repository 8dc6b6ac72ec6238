package robosim.params;

import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ParameterFileReaderTest {
    private static RobotParameters p3dx;
    private static RobotParameters p3at;

    @TempDir
    Path dir;

    @BeforeAll
    static void readShippedFiles() {
        p3dx = ParameterFileReader.read(ShippedRobots.dir().resolve("p3dx.p"));
        p3at = ParameterFileReader.read(ShippedRobots.dir().resolve("p3at.p"));
    }

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.UTF_8);
    }

    private static void assertNamesFileLineAndRule(Path file, int line, String rule, ParameterFileException e) {
        assertEquals(file + ":" + line + ": " + rule, e.getMessage());
    }

    // --- the shipped Pioneer files match docs/ARIA-SEMANTICS.md ---

    @Test
    void p3dxIsAPioneerP3dx() {
        assertEquals("Pioneer", p3dx.robotClass());
        assertEquals("p3dx", p3dx.subclass());
    }

    @Test
    void p3dxBody() {
        assertEquals(250, p3dx.robotRadius());
        assertEquals(425, p3dx.robotWidth());
        assertEquals(511, p3dx.robotLength());
        assertEquals(210, p3dx.robotLengthFront());
        assertEquals(301, p3dx.robotLengthRear());
    }

    @Test
    void p3dxMaximumVelocities() {
        assertEquals(2200, p3dx.maxVelocity());
        assertEquals(500, p3dx.maxRVelocity());
    }

    @Test
    void p3dxHasSixteenSonarsInIndexOrder() {
        assertEquals(16, p3dx.sonarUnits().size());
        for (int i = 0; i < 16; i++) {
            assertEquals(i, p3dx.sonarUnits().get(i).index());
        }
    }

    @ParameterizedTest(name = "p3dx sonar {0}: {1}, {2}, {3}")
    @CsvSource({
        "0, 69, 136, 90", "1, 114, 119, 50", "2, 148, 78, 30", "3, 166, 27, 10",
        "4, 166, -27, -10", "5, 148, -78, -30", "6, 114, -119, -50", "7, 69, -136, -90",
        "8, -157, -136, -90", "9, -203, -119, -130", "10, -237, -78, -150", "11, -255, -27, -170",
        "12, -255, 27, 170", "13, -237, 78, 150", "14, -203, 119, 130", "15, -157, 136, 90",
    })
    void p3dxSonarPoseMatchesAriaTable(int n, double x, double y, double th) {
        assertEquals(new SonarUnit(n, x, y, th), p3dx.sonarUnits().get(n));
    }

    @Test
    void p3dxOtherValues() {
        assertEquals(300, p3dx.transAccel());
        assertEquals(300, p3dx.transDecel());
        assertEquals(100, p3dx.rotAccel());
        assertEquals(100, p3dx.rotDecel());
        assertEquals(0.0056, p3dx.diffConvFactor());
        assertEquals(5000, p3dx.sonarMaxRange());
    }

    @Test
    void p3atIsAPioneerP3at() {
        assertEquals("Pioneer", p3at.robotClass());
        assertEquals("p3at", p3at.subclass());
    }

    @Test
    void p3atBody() {
        assertEquals(500, p3at.robotRadius());
        assertEquals(505, p3at.robotWidth());
        assertEquals(626, p3at.robotLength());
        assertEquals(313, p3at.robotLengthFront());
        assertEquals(313, p3at.robotLengthRear());
    }

    @Test
    void p3atMaximumVelocities() {
        assertEquals(1200, p3at.maxVelocity());
        assertEquals(300, p3at.maxRVelocity());
    }

    @Test
    void p3atHasSixteenSonarsInIndexOrder() {
        assertEquals(16, p3at.sonarUnits().size());
        for (int i = 0; i < 16; i++) {
            assertEquals(i, p3at.sonarUnits().get(i).index());
        }
    }

    @ParameterizedTest(name = "p3at sonar {0}: {1}, {2}, {3}")
    @CsvSource({
        "0, 147, 136, 90", "1, 193, 119, 50", "2, 227, 79, 30", "3, 245, 27, 10",
        "4, 245, -27, -10", "5, 227, -79, -30", "6, 193, -119, -50", "7, 147, -136, -90",
        "8, -144, -136, -90", "9, -189, -119, -130", "10, -223, -79, -150", "11, -241, -27, -170",
        "12, -241, 27, 170", "13, -223, 79, 150", "14, -189, 119, 130", "15, -144, 136, 90",
    })
    void p3atSonarPoseMatchesAriaTable(int n, double x, double y, double th) {
        assertEquals(new SonarUnit(n, x, y, th), p3at.sonarUnits().get(n));
    }

    // --- reading rules ---

    @Test
    void absentKeysKeepAriaDefaults() throws IOException {
        Path file = write("bare.p", "ConfigVersion 2.0\n");

        RobotParameters p = ParameterFileReader.read(file);

        assertEquals(new RobotParameters("Pioneer", "bare", 250, 400, 250, 250, 2500, 500, 300, 300, 100, 100,
                0.0056, 5000, List.of()), p);
    }

    @Test
    void lengthWithoutFrontAndRearIsSplitEvenly() throws IOException {
        Path file = write("even.p", """
                ConfigVersion 2.0
                RobotLength 600
                """);

        RobotParameters p = ParameterFileReader.read(file);

        assertEquals(300, p.robotLengthFront());
        assertEquals(300, p.robotLengthRear());
    }

    @Test
    void keysMatchWithoutRegardToCase() throws IOException {
        Path file = write("case.p", """
                ConfigVersion 2.0
                robotwidth 333
                MAXVELOCITY 1500
                """);

        RobotParameters p = ParameterFileReader.read(file);

        assertEquals(333, p.robotWidth());
        assertEquals(1500, p.maxVelocity());
    }

    @Test
    void keysRoboSimDoesNotModelAreIgnored() throws IOException {
        Path file = write("extra.p", """
                ConfigVersion 2.0
                DistConvFactor 0.485 ; unused
                SwitchToBaudRate 38400
                RobotWidth 425
                """);

        assertEquals(425, ParameterFileReader.read(file).robotWidth());
    }

    @Test
    void missingFileIsAnUncheckedIoErrorNamingIt() {
        Path file = dir.resolve("absent.p");

        UncheckedIOException e = assertThrows(UncheckedIOException.class, () -> ParameterFileReader.read(file));

        assertEquals("cannot read robot parameter file " + file, e.getMessage());
    }

    // --- broken files name the file, the line and the rule ---

    /** Such a file was "cannot read robot parameter file", with the decoder's "Input length = 1" as the cause. */
    @Test
    void aByteThatIsNotUtf8IsNamedWithItsLineAndOffset() throws IOException {
        Path file = dir.resolve("latin1.p");
        Files.write(file, "ConfigVersion 2.0\r\nClass Pioneer\r\nSubclass caf\u00e9\r\n".getBytes(StandardCharsets.ISO_8859_1));

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 3, "byte 0xe9 at byte offset 46 is not UTF-8: a parameter file is UTF-8 text", e);
    }

    @Test
    void aByteOrderMarkIsSkipped() throws IOException {
        Path file = write("bom.p", "\ufeffConfigVersion 2.0\nRobotWidth 425\n");

        assertEquals(425, ParameterFileReader.read(file).robotWidth());
    }

    @Test
    void keyBeforeConfigVersionIsRejected() throws IOException {
        Path file = write("noversion.p", """
                ; a robot without a version line
                Section General settings
                RobotRadius 250
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 2, "expected 'ConfigVersion 2.0' before 'Section'", e);
    }

    @Test
    void fileWithNoConfigVersionAtAllIsRejected() throws IOException {
        Path file = write("comments.p", """
                ; only comments

                ; and blank lines
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertEquals(file + ": no 'ConfigVersion 2.0' line: not an ARIA parameter file", e.getMessage());
    }

    @Test
    void nonNumericValueIsRejected() throws IOException {
        Path file = write("word.p", """
                ConfigVersion 2.0
                Section General settings
                RobotRadius 250
                MaxVelocity fast ; mm/s
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 4, "MaxVelocity 'fast' is not a number", e);
    }

    @Test
    void nonNumericSonarCoordinateIsRejected() throws IOException {
        Path file = write("sonarword.p", """
                ConfigVersion 2.0
                SonarNum 1
                SonarUnit 0 69 left 90
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 3, "SonarUnit y 'left' is not a number", e);
    }

    @Test
    void sonarUnitWithTooFewValuesIsRejected() throws IOException {
        Path file = write("short.p", """
                ConfigVersion 2.0
                SonarNum 2
                SonarUnit 0 69 136 90
                SonarUnit 1 114 119
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 4, "SonarUnit needs at least 4 values (index x y th), found 3", e);
    }

    @Test
    void sonarIndexNotBelowSonarNumIsRejected() throws IOException {
        Path file = write("index.p", """
                ConfigVersion 2.0
                SonarNum 2
                SonarUnit 0 69 136 90
                SonarUnit 1 114 119 50
                SonarUnit 2 148 78 30
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 5, "SonarUnit index 2 must be less than SonarNum 2", e);
    }

    @Test
    void sonarIndexBeyondALaterSonarNumIsRejected() throws IOException {
        Path file = write("late.p", """
                ConfigVersion 2.0
                SonarUnit 0 69 136 90
                SonarUnit 5 148 78 30
                SonarNum 1
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 3, "SonarUnit index 5 must be less than SonarNum 1", e);
    }

    @Test
    void negativeSonarIndexIsRejected() throws IOException {
        Path file = write("negindex.p", """
                ConfigVersion 2.0
                SonarUnit -1 69 136 90
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 2, "SonarUnit index -1 must be a whole number from 0", e);
    }

    @Test
    void duplicateSonarUnitIsRejected() throws IOException {
        Path file = write("twice.p", """
                ConfigVersion 2.0
                SonarNum 2
                SonarUnit 0 69 136 90
                SonarUnit 1 114 119 50
                SonarUnit 1 148 78 30
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 5, "SonarUnit 1 is given twice", e);
    }

    @Test
    void missingSonarUnitIsRejectedAtTheSonarNumLine() throws IOException {
        Path file = write("gap.p", """
                ConfigVersion 2.0
                Section Sonar parameters
                SonarNum 3
                SonarUnit 0 69 136 90
                SonarUnit 2 148 78 30
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 3, "SonarNum is 3 but there is no SonarUnit 1", e);
    }

    @Test
    void fractionalSonarNumIsRejected() throws IOException {
        Path file = write("half.p", """
                ConfigVersion 2.0
                SonarNum 2.5
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 2, "SonarNum 2.5 must be a whole number from 0 to 32", e);
    }

    @Test
    void negativeRobotWidthIsRejected() throws IOException {
        Path file = write("width.p", """
                ConfigVersion 2.0
                Section General settings
                RobotWidth -425 ; width in mm
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 3, "RobotWidth is -425 but must be greater than 0", e);
    }

    @Test
    void zeroMaxVelocityIsRejected() throws IOException {
        Path file = write("still.p", """
                ConfigVersion 2.0
                MaxVelocity 0
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 2, "MaxVelocity is 0 but must be greater than 0", e);
    }

    @Test
    void keyWithoutValueIsRejected() throws IOException {
        Path file = write("novalue.p", """
                ConfigVersion 2.0
                Subclass
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertNamesFileLineAndRule(file, 2, "Subclass has no value", e);
    }
}
