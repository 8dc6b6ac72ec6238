package robosim.params;

import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The laser keys of ARIA's {@code .p} form, and the rules that came with them. */
class ParameterFileReaderLaserTest {
    @TempDir
    Path dir;

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.UTF_8);
    }

    private static List<Double> laser(RobotParameters p) {
        return List.of(p.laserX(), p.laserY(), p.laserTh(), p.laserMaxRange());
    }

    @Test
    void laserKeysGiveTheMountingPoseAndRange() throws IOException {
        Path file = write("laser.p", """
                ConfigVersion 2.0
                Section Laser parameters
                LaserX 18   ; mm
                LaserY -5   ; mm
                LaserTh 180 ; deg
                LaserMaxRange 32000
                """);

        assertEquals(List.of(18.0, -5.0, 180.0, 32000.0), laser(ParameterFileReader.read(file)));
    }

    @Test
    void noLaserKeysPutTheLaserAtTheCentreWithItsDefaultRange() throws IOException {
        Path file = write("nolaser.p", "ConfigVersion 2.0\n");

        assertEquals(List.of(0.0, 0.0, 0.0, RobotParameters.DEFAULT_LASER_MAX_RANGE),
                laser(ParameterFileReader.read(file)));
    }

    @Test
    void laserMaxRangeZeroMeansTheDefaultAsInAria() throws IOException {
        Path file = write("zero.p", """
                ConfigVersion 2.0
                LaserMaxRange 0 ; Max range to use for the laser, 0 to use default
                """);

        assertEquals(8000, ParameterFileReader.read(file).laserMaxRange());
    }

    @Test
    void ariasOtherLaserKeysAreIgnored() throws IOException {
        Path file = write("aria.p", """
                ConfigVersion 2.0
                Section Laser parameters
                LaserPossessed true
                LaserPort COM3
                LaserFlipped false
                LaserPowerControlled true
                LaserType lms2xx
                LaserIgnore            ; Readings within a degree of the listed degrees will be ignored
                LaserStartDegrees
                LaserX 160
                """);

        assertEquals(160, ParameterFileReader.read(file).laserX());
    }

    @Test
    void laserKeysOfASecondLaserSectionAreIgnored() throws IOException {
        Path file = write("two.p", """
                ConfigVersion 2.0
                Section Laser 1 parameters
                LaserX 18
                Section Laser 2 parameters
                LaserX -200
                LaserTh 180
                """);

        RobotParameters p = ParameterFileReader.read(file);

        assertEquals(List.of(18.0, 0.0), List.of(p.laserX(), p.laserTh()));
    }

    @Test
    void negativeLaserMaxRangeIsRejected() throws IOException {
        Path file = write("negrange.p", """
                ConfigVersion 2.0
                LaserMaxRange -1
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertEquals(file + ":2: LaserMaxRange is -1 but must not be negative", e.getMessage());
    }

    @Test
    void nonNumericLaserPoseIsRejected() throws IOException {
        Path file = write("word.p", """
                ConfigVersion 2.0
                Section Laser parameters
                LaserTh ahead
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertEquals(file + ":3: LaserTh 'ahead' is not a number", e.getMessage());
    }

    @Test
    void negativeRobotLengthIsRejectedAsNegativeNotAsZero() throws IOException {
        Path file = write("length.p", """
                ConfigVersion 2.0
                RobotLength -511
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertEquals(file + ":2: RobotLength is -511 but must not be negative", e.getMessage());
    }

    @Test
    void zeroRobotDiagonalIsRejected() throws IOException {
        Path file = write("diagonal.p", """
                ConfigVersion 2.0
                RobotDiagonal 0
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertEquals(file + ":2: RobotDiagonal is 0 but must be greater than 0", e.getMessage());
    }

    @Test
    void sonarIndexBeyondTheMostSonarsIsRejectedWithoutSonarNum() throws IOException {
        Path file = write("far.p", """
                ConfigVersion 2.0
                SonarUnit 2000000000 0 0 0
                """);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));

        assertEquals(file + ":2: SonarUnit index 2000000000 must be less than 32", e.getMessage());
    }
}
