package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A world file whose value is 400 000 characters long and holds control characters is refused with a short error
 * that still names the file, the line, the attribute and the rule, quoting an escaped excerpt of
 * the value: no file can fill a terminal or write to it through an error.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class WorldFileExcerptTest {
    /**
     * 400 000 characters with a line break and a tab after the first, as XML writes them (XML refuses
     * ESC and BEL even as references, so a world file cannot hold them; the parser refuses an
     * attribute over 512 KiB itself, in a short line).
     */
    private static final String HUGE = "x&#10;&#9;" + "x".repeat(400_000);

    @TempDir
    Path dir;

    @ParameterizedTest
    @ValueSource(strings = {
        "<world name=\"w\" width=\"HUGE\" height=\"1000\"/>",
        "<world name=\"w\" width=\"1000\" height=\"1000\" boundary=\"HUGE\"/>",
        "<world name=\"w\" width=\"1000\" height=\"1000\" motors=\"HUGE\"/>",
        "<world name=\"HUGE\" width=\"1000\" height=\"1000\"/>",
        "<world name=\"w\" width=\"1000\" height=\"1000\">\n<wall x1=\"0\" y1=\"0\" x2=\"500\" y2=\"0\" color=\"HUGE\"/></world>",
        "<world name=\"w\" width=\"1000\" height=\"1000\">\n<robot name=\"HUGE\" type=\"pioneer\" x=\"500\" y=\"500\""
            + " params=\"p3dx\"/></world>",
        "<world name=\"w\" width=\"1000\" height=\"1000\">\n<robot name=\"r1\" type=\"pioneer\" x=\"500\" y=\"500\""
            + " params=\"HUGE\"/></world>",
        "<world name=\"w\" width=\"1000\" height=\"1000\">\n<robot name=\"r1\" type=\"HUGE\" x=\"500\" y=\"500\""
            + " params=\"p3dx\"/></world>",
        "<world name=\"w\" width=\"1000\" height=\"1000\">\n<object type=\"HUGE\" x=\"500\" y=\"500\"/></world>",
        "<world name=\"w\" width=\"1000\" height=\"1000\">\n<property name=\"HUGE\" value=\"1\"/></world>",
        "<world name=\"w\" width=\"1000\" height=\"1000\">\n<end when=\"HUGE\"/></world>",
    })
    void aHugeValueWithControlCharactersGivesAShortEscapedError(String world) throws IOException {
        Path file = Files.writeString(dir.resolve("huge.xml"), world.replace("HUGE", HUGE), StandardCharsets.UTF_8);

        WorldFileException e = assertThrows(WorldFileException.class, () -> WorldReader.read(file));

        String message = e.getMessage();
        assertTrue(message.length() < 600, () -> message.length() + " characters: " + message.substring(0, 600));
        assertTrue(message.chars().noneMatch(c -> c < 0x20 || c == 0x7f), message);
        assertTrue(message.startsWith(file + ":"), message);
        assertTrue(e.line() >= 1, message);
        assertTrue(message.contains("x\\u000a\\u0009xxx") && message.contains("characters)"), message);
    }

    @ParameterizedTest
    @ValueSource(strings = {"<HUGE/>", "<world name=\"w\" width=\"1000\" height=\"1000\"><HUGE/></world>",
        "<world name=\"w\" width=\"1000\" height=\"1000\" HUGE=\"1\"/>"})
    void aHugeElementOrAttributeNameGivesAShortError(String world) throws IOException {
        Path file = Files.writeString(dir.resolve("names.xml"), world.replace("HUGE", "n".repeat(1 << 20)),
                StandardCharsets.UTF_8);

        WorldFileException e = assertThrows(WorldFileException.class, () -> WorldReader.read(file));

        assertTrue(e.getMessage().length() < 600, () -> e.getMessage().substring(0, 600));
        assertTrue(e.getMessage().contains("characters)"), e.getMessage());
    }
}
