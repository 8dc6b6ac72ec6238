package robosim.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** {@code HasGripper}: whether a Pioneer gripper is mounted. */
class ParameterFileReaderGripperTest {
    @TempDir
    Path dir;

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.UTF_8);
    }

    @Test
    void theShippedP3dxHasNoneAndItsGripperFormHasOne() {
        assertFalse(ParameterFileReader.read(ShippedRobots.dir().resolve("p3dx.p")).hasGripper());
        assertTrue(ParameterFileReader.read(ShippedRobots.dir().resolve("p3dx-gripper.p")).hasGripper());
    }

    @ParameterizedTest
    @CsvSource({"true, true", "1, true", "FALSE, false", "0, false"})
    void hasGripperTakesBooleansAsAriaWritesThem(String value, boolean expected) throws IOException {
        Path file = write("g.p", "ConfigVersion 2.0\nHasGripper " + value + " ; the gripper\n");
        assertEquals(expected, ParameterFileReader.read(file).hasGripper());
    }

    @Test
    void anotherValueIsRefusedNamingTheLine() throws IOException {
        Path file = write("g.p", "ConfigVersion 2.0\n\nHasGripper maybe\n");
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> ParameterFileReader.read(file));
        assertTrue(e.getMessage().contains("g.p:3"), e.getMessage());
        assertTrue(e.getMessage().contains("HasGripper 'maybe' must be true, false, 1 or 0"), e.getMessage());
    }
}
