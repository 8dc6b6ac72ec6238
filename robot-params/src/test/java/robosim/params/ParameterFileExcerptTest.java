package robosim.params;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A parameter file, of either form, whose value is a megabyte long and holds control characters is refused
 * with a short error that names the file, the line and the rule, quoting an escaped excerpt.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class ParameterFileExcerptTest {
    private static final String HUGE = "\u001b[2J\u0007" + "7".repeat(1 << 20);
    /** XML refuses ESC and BEL even as references: a line break and a tab are what it can carry. */
    private static final String HUGE_XML = "&#10;&#9;" + "7".repeat(1 << 20);

    @TempDir
    Path dir;

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "huge.p|ConfigVersion 2.0\\nMaxVelocity HUGE\\n",
        "huge.p|ConfigVersion 2.0\\nRobotShape HUGE\\n",
        "huge.p|ConfigVersion 2.0\\nHUGE 1\\n",
        "huge.p|HUGE\\n",
        "huge.xml|<robotParameters><maxVelocity>HUGE_XML</maxVelocity></robotParameters>",
        "huge.xml|<robotParameters>HUGE_XML</robotParameters>",
        "huge.xml|<robotParameters><nHUGE_NAME/></robotParameters>",
    })
    void aHugeValueWithControlCharactersGivesAShortEscapedError(String name, String text) throws IOException {
        Path file = Files.writeString(dir.resolve(name), text.replace("\\n", "\n").replace("HUGE_XML", HUGE_XML)
                .replace("HUGE_NAME", "n".repeat(1 << 20)).replace("HUGE", HUGE), StandardCharsets.UTF_8);

        ParameterFileException e = assertThrows(ParameterFileException.class, () -> RobotParametersReader.read(file));

        String message = e.getMessage();
        assertTrue(message.length() < 600, () -> message.length() + " characters: " + message.substring(0, 600));
        assertTrue(message.chars().noneMatch(c -> c < 0x20 || c == 0x7f), message);
        assertTrue(message.contains(file.getFileName().toString()), message);
        assertTrue(message.contains("characters)"), message);
    }
}
