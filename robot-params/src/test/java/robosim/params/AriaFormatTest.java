package robosim.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/** ARIA's files as ARIA writes them load unchanged: the features of its newer files, as literal fixtures. */
class AriaFormatTest {
    private static final Logger LOG = Logger.getLogger(ParameterRules.class.getName());
    private final List<LogRecord> warnings = new ArrayList<>();
    private final Handler handler = new Handler() {
        @Override
        public void publish(LogRecord r) {
            if (r.getLevel().intValue() >= Level.WARNING.intValue()) {
                warnings.add(r);
            }
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    };

    @TempDir
    Path dir;

    @BeforeEach
    void listen() {
        LOG.addHandler(handler);
    }

    @AfterEach
    void stopListening() {
        LOG.removeHandler(handler);
    }

    private Path write(String name, String... lines) throws IOException {
        return Files.writeString(dir.resolve(name), String.join("\n", lines) + "\n", StandardCharsets.UTF_8);
    }

    @Test
    void zeroAccelerationsAndSpeedLimitsKeepTheFirmwaresValues() throws IOException {
        Path file = write("zero.p", "ConfigVersion 2.0", "Section Movement control parameters",
                "TransVelMax 0", "RotVelMax 0", "TransAccel 0", "TransDecel 0", "RotAccel 0", "RotDecel 0");
        RobotParameters p = ParameterFileReader.read(file);
        assertEquals(List.of(300.0, 300.0, 100.0, 100.0),
                List.of(p.transAccel(), p.transDecel(), p.rotAccel(), p.rotDecel()));
        assertEquals(List.of(), warnings);
    }

    @Test
    void aNegativeAccelerationIsStillRefused() throws IOException {
        Path file = write("neg.p", "ConfigVersion 2.0", "TransAccel -5");
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));
        assertEquals(file + ":2: TransAccel is -5 but must be greater than 0", e.getMessage());
    }

    @Test
    void mtxSonarUnitLinesGiveTheirPose() throws IOException {
        Path file = write("lx.p", "ConfigVersion 2.0", "Section Sonar parameters", "SonarNum 2",
                "SonarUnit 0 150 100 45 1 1 0 0 3000 true", "SonarUnit 1 -150 -100 -135 1 2");
        RobotParameters p = ParameterFileReader.read(file);
        assertEquals(List.of(new SonarUnit(0, 150, 100, 45), new SonarUnit(1, -150, -100, -135)), p.sonarUnits());
    }

    @Test
    void moreSonarsDeclaredThanListedLoadTheListedOnesWithOneWarning() throws IOException {
        Path file = write("pb.p", "ConfigVersion 2.0", "SonarNum 4", "SonarUnit 0 1 2 3", "SonarUnit 1 4 5 6",
                "FlyingCarpet true");
        RobotParameters p = ParameterFileReader.read(file);
        assertEquals(2, p.sonarUnits().size());
        assertEquals(1, warnings.size());
        assertEquals(file + ": ignored unknown key FlyingCarpet (line 5); SonarNum is 4 (line 2) but only 2 "
                + "SonarUnits are given; the robot has those 2", warnings.get(0).getMessage());
    }

    @Test
    void aGapInTheSonarsIsStillRefused() throws IOException {
        Path file = write("gap.p", "ConfigVersion 2.0", "SonarNum 4", "SonarUnit 0 1 2 3", "SonarUnit 2 4 5 6");
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));
        assertEquals(file + ":2: SonarNum is 4 but there is no SonarUnit 1", e.getMessage());
    }

    @Test
    void aSonarBoardsMaxRangeIsNotTheRingsRange() throws IOException {
        Path file = write("board.p", "ConfigVersion 2.0", "Section Sonar parameters", "SonarMaxRange 3000",
                "Section SonarBoard_1", "SonarAutoConnect false", "SonarBoardType", "SonarMaxRange 4335",
                "[SonarBoard_2]", "SonarMaxRange 17");
        assertEquals(3000, ParameterFileReader.read(file).sonarMaxRange());
        assertEquals(List.of(), warnings);
    }

    @Test
    void bracketedSectionHeadersAreSections() throws IOException {
        Path file = write("brackets.p", "ConfigVersion 2.0", "[General settings]", "RobotWidth 333",
                "[Laser 2 parameters]", "LaserX 999", "[Laser parameters]", "LaserX 18");
        RobotParameters p = ParameterFileReader.read(file);
        assertEquals(333, p.robotWidth());
        assertEquals(18, p.laserX());
    }

    @Test
    void ariaKeysRoboSimDoesNotModelPassWithoutAWarning() throws IOException {
        Path file = write("aria.p", "ConfigVersion 2.0", "Section General settings", "Holonomic true",
                "HasMoveCommand true", "Section Accessories the robot has", "FrontBumpers true",
                "Section IR parameters", "IRNum 1", "IRUnit 0 1 2 300 -180", "Section PTZ 1 parameters",
                "PTZType vcc4", "Section Laser parameters", "LaserPossibleConnections", "LaserType lms2xx");
        ParameterFileReader.read(file);
        assertEquals(List.of(), warnings);
    }

    @Test
    void unknownSectionsAndKeysAreNamedInOneWarning() throws IOException {
        Path file = write("odd.p", "ConfigVersion 2.0", "Section Teleporter", "BeamPower 11", "Range 3",
                "Section General settings", "RobotWidth 410", "WheelCount 4 ; a comment");
        assertEquals(410, ParameterFileReader.read(file).robotWidth());
        assertEquals(1, warnings.size());
        String message = warnings.get(0).getMessage();
        assertEquals(file + ": ignored unknown keys BeamPower (line 3), Range (line 4), WheelCount (line 7)", message);
    }

    @Test
    void manyUnknownKeysAreCountedPastTheFirstTwenty() throws IOException {
        List<String> lines = new ArrayList<>(List.of("ConfigVersion 2.0"));
        for (int i = 0; i < 25; i++) {
            lines.add("Odd" + i + " 1");
        }
        Path file = write("many.p", lines.toArray(String[]::new));
        ParameterFileReader.read(file);
        assertEquals(1, warnings.size());
        assertTrue(warnings.get(0).getMessage().endsWith("Odd19 (line 21) and 5 more"), warnings.get(0).getMessage());
    }

    @Test
    void conversionFactorsComeFromTheirSection() throws IOException {
        Path file = write("cf.p", "ConfigVersion 2.0", "Section Conversion factors", "AngleConvFactor 0.00153",
                "DistConvFactor 0.485", "VelConvFactor 1.0", "RangeConvFactor 1.0", "DiffConvFactor 0.0056",
                "Vel2Divisor 20");
        assertEquals(new ConversionFactors(0.00153, 0.485, 1.0, 1.0, 0.0056, 20),
                ParameterFileReader.conversionFactors(file));
    }

    @Test
    void absentConversionFactorsKeepAriasDefaults() throws IOException {
        Path file = write("none.p", "ConfigVersion 2.0", "DistConvFactor 0.826");
        ConversionFactors f = ParameterFileReader.conversionFactors(file);
        assertEquals(ConversionFactors.ARIA_DEFAULTS.angleConvFactor(), f.angleConvFactor());
        assertEquals(0.826, f.distConvFactor());
        assertEquals(20, f.vel2Divisor());
        assertTrue(Math.abs(2 * Math.PI / 4096 - ConversionFactors.ARIA_DEFAULTS.angleConvFactor()) < 1e-6);
    }

    @Test
    void aBadConversionFactorNamesTheFileAndLine() throws IOException {
        Path file = write("badcf.p", "ConfigVersion 2.0", "Section Conversion factors", "DistConvFactor 0");
        ParameterFileException e = assertThrows(ParameterFileException.class,
                () -> ParameterFileReader.conversionFactors(file));
        assertEquals(file + ":3: DistConvFactor is 0 but must be greater than 0", e.getMessage());
    }
}
