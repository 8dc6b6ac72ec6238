package robosim.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The bumper keys of ARIA's {@code .p} form (ArRobotParams.cpp) and RoboSim's SonarCycle. */
class RobotSpecificKeysTest {
    @TempDir
    Path dir;

    private Path write(String text) throws IOException {
        return Files.writeString(dir.resolve("bump.p"), text, StandardCharsets.UTF_8);
    }

    @Test
    void aFileWithoutBumperKeysHasArisDefaults() throws IOException {
        Path file = write("ConfigVersion 2.0\nSection General settings\nClass Pioneer\n");
        assertEquals(new BumperParameters(false, 5, false, 5), ParameterFileReader.bumpers(file));
    }

    @Test
    void theKeysAreReadWithoutRegardToCase() throws IOException {
        Path file = write("""
                ConfigVersion 2.0
                Section General settings
                frontbumpers true ; a ring
                NumFrontBumpers 7
                RearBumpers 1
                NUMREARBUMPERS 3
                """);
        assertEquals(new BumperParameters(true, 7, true, 3), ParameterFileReader.bumpers(file));
    }

    @Test
    void tooManyBumpersNameTheFileAndLine() throws IOException {
        Path file = write("ConfigVersion 2.0\nNumFrontBumpers 8\n");
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.bumpers(file));
        assertTrue(e.getMessage().contains("bump.p"), e.getMessage());
        assertTrue(e.getMessage().contains("2"), e.getMessage());
        assertTrue(e.getMessage().contains("NumFrontBumpers is 8 but a bump ring has 1 to 7 bumpers"), e.getMessage());
    }

    @Test
    void aFlagThatIsNotABooleanIsAnError() throws IOException {
        Path file = write("ConfigVersion 2.0\nRearBumpers maybe\n");
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.bumpers(file));
        assertTrue(e.getMessage().contains("RearBumpers 'maybe' is not a boolean"), e.getMessage());
    }

    @Test
    void theShippedP3dxHasFrontAndRearRingsOfFive() {
        Path root = Path.of("").toAbsolutePath();
        while (!Files.isDirectory(root.resolve("testLoadFiles"))) {
            root = root.getParent();
        }
        assertEquals(new BumperParameters(true, 5, true, 5),
                ParameterFileReader.bumpers(root.resolve("testLoadFiles/robots/p3dx.p")));
    }

    @Test
    void sonarCycleIsReadAndCheckedWithItsLine() throws IOException {
        assertEquals(40, ParameterFileReader.sonarCycle(write("ConfigVersion 2.0\nSonarCycle 40 ; ms\n")));
        assertEquals(0, ParameterFileReader.sonarCycle(write("ConfigVersion 2.0\n")));
        Path bad = write("ConfigVersion 2.0\n\nSonarCycle -5\n");
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.sonarCycle(bad));
        assertTrue(e.getMessage().contains("3"), e.getMessage());
        assertTrue(e.getMessage().contains("SonarCycle is -5 but must be 0 (every step) to 10000 ms"), e.getMessage());
    }
}
