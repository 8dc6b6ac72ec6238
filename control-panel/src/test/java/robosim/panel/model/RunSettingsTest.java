package robosim.panel.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RunSettingsTest {
    @TempDir
    Path dir;

    private Path world() throws IOException {
        return Files.writeString(dir.resolve("room.xml"), "<world/>");
    }

    @Test
    void theSettingsBecomeEnvsArgumentsWithTheSecretFile() throws IOException {
        Path w = world();
        RunSettings s = RunSettings.parse(w.toString(), "7", "", "5001", " ");

        assertEquals(List.of("env", w.toString(), "--seed", "7", "--robot-port", "0", "--viewer-port", "5001",
                "--bind", "127.0.0.1", "--token-file", "/tmp/s"), s.envArguments(Path.of("/tmp/s")));
    }

    @Test
    void aMissingWorldFileIsNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RunSettings.parse(dir.resolve("none.xml").toString(), "1", "0", "0", ""));

        assertEquals("World: no such file: " + dir.resolve("none.xml"), e.getMessage());
    }

    @Test
    void aSeedThatIsNotAWholeNumberIsRefused() throws IOException {
        Path w = world();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RunSettings.parse(w.toString(), "1.5", "0", "0", ""));

        assertEquals("Seed: a whole number (64 bits), got '1.5'", e.getMessage());
    }

    @Test
    void aPortOutOfRangeIsRefusedNamingTheField() throws IOException {
        Path w = world();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RunSettings.parse(w.toString(), "1", "70000", "0", ""));

        assertEquals("Robot port: 0 (any free port) or a port from 1 to 65535, got '70000'", e.getMessage());
    }

    @Test
    void theSamePortForRobotsAndViewersIsRefused() throws IOException {
        Path w = world();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RunSettings.parse(w.toString(), "1", "5000", "5000", ""));

        assertEquals("Viewer port: must differ from the robot port, both are 5000", e.getMessage());
    }
}
