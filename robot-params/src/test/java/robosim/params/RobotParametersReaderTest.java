package robosim.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Choosing the reader by the file's extension. */
class RobotParametersReaderTest {
    private static final String P_FORM = """
            ConfigVersion 2.0
            RobotWidth 333
            """;
    private static final String XML_FORM = """
            <robotParameters>
              <robotWidth>444</robotWidth>
            </robotParameters>
            """;

    @TempDir
    Path dir;

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.UTF_8);
    }

    @Test
    void dotPIsReadAsAriasForm() throws IOException {
        Path file = write("robot.p", P_FORM);

        assertEquals(333, RobotParametersReader.read(file).robotWidth());
    }

    @Test
    void dotXmlIsReadAsTheXmlForm() throws IOException {
        Path file = write("robot.xml", XML_FORM);

        assertEquals(444, RobotParametersReader.read(file).robotWidth());
    }

    @Test
    void extensionsMatchInAnyCase() throws IOException {
        Path p = write("ROBOT.P", P_FORM);
        Path xml = write("Robot.XML", XML_FORM);

        assertEquals(333, RobotParametersReader.read(p).robotWidth());
        assertEquals(444, RobotParametersReader.read(xml).robotWidth());
    }

    @Test
    void theExtensionDecidesNotTheContent() throws IOException {
        Path file = write("xml-inside.p", XML_FORM);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> RobotParametersReader.read(file));

        assertEquals(file + ":1: expected 'ConfigVersion 2.0' before '<robotParameters>'", e.getMessage());
    }

    @ParameterizedTest(name = "''{0}'' is refused, naming the known extensions")
    @ValueSource(strings = {"robot.txt", "robot", "robot.params", "robot.p.bak"})
    void unknownExtensionIsRejectedNamingTheKnownOnes(String name) throws IOException {
        Path file = write(name, P_FORM);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> RobotParametersReader.read(file));

        assertEquals(file + ": not a robot parameter file: the known extensions are .p (ARIA's form) and .xml "
                + "(RoboSim's form)", e.getMessage());
    }
}
