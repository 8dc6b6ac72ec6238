package robosim.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** Maps made to hurt: huge lines, terminal escapes, more than the heap can take. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class HostileMapTest {
    /** The longest message a hostile map may cause: its path, a line number, a rule and a short excerpt. */
    private static final int MAX_MESSAGE = 600;

    @TempDir
    Path dir;

    private MapFileException fails(Path file, long maxHeap) {
        MapFileException e = assertThrows(MapFileException.class, () -> MapReader.read(file, maxHeap));
        assertTrue(e.getMessage().length() < MAX_MESSAGE, e.getMessage().length() + " characters: " + e.getMessage());
        assertFalse(e.getMessage().chars().anyMatch(c -> c < 0x20 || c >= 0x7f),
                "a character outside printable ASCII reached the message: " + e.getMessage());
        return e;
    }

    private Path write(String name, String text) throws IOException {
        return Files.write(dir.resolve(name), text.getBytes(StandardCharsets.ISO_8859_1));
    }

    @Test
    void aHundredMegabyteLineIsRefusedAtTheLimitWithAShortMessage() throws IOException {
        Path file = dir.resolve("long.map");
        try (OutputStream out = Files.newOutputStream(file)) {
            out.write("2D-Map\nDATA\n".getBytes(StandardCharsets.US_ASCII));
            byte[] digits = new byte[1 << 20];
            java.util.Arrays.fill(digits, (byte) '1');
            for (int i = 0; i < 100; i++) {
                out.write(digits);
            }
        }
        MapFileException e = fails(file, Long.MAX_VALUE);
        assertEquals(3, e.line());
        assertTrue(e.rule().startsWith("the line is longer than " + MapLines.MAX_LENGTH + " characters"), e.rule());
        assertTrue(e.getMessage().startsWith(file + ":3: "), e.getMessage());
    }

    @Test
    void aLineJustUnderTheLimitIsRead() throws IOException {
        String padded = "1" + " ".repeat(MapLines.MAX_LENGTH - 3) + "2";
        MapFile map = MapReader.read(write("padded.map", "2D-Map\nDATA\n" + padded + "\n"), Long.MAX_VALUE);
        assertEquals(1, map.pointCount());
    }

    @Test
    void aLongNumberIsQuotedShort() throws IOException {
        MapFileException e = fails(write("big.map", "2D-Map\nDATA\n1 " + "9".repeat(10_000) + "\n"), Long.MAX_VALUE);
        assertEquals(3, e.line());
        assertTrue(e.rule().contains("... (10000 characters) must be from -1000000000 to 1000000000"), e.rule());
    }

    @Test
    void escapeAndBellAreEscapedInEveryQuote() throws IOException {
        String esc = "\u001b[31m\u0007";
        MapFileException point = fails(write("esc1.map", "2D-Map\nDATA\n1 " + esc + "\n"), Long.MAX_VALUE);
        assertTrue(point.rule().contains("coordinate '\\u001b[31m\\u0007' is not a number"), point.rule());
        MapFileException header = fails(write("esc2.map", "2D-Map\n" + esc + "\nDATA\n"), Long.MAX_VALUE);
        assertTrue(header.rule().startsWith("'\\u001b[31m\\u0007' is neither"), header.rule());
        MapFileException cairn = fails(write("esc3.map", "2D-Map\nCairn: Goal" + esc + " x 0 0 \"\" ICON \"g\"\n"),
                Long.MAX_VALUE);
        assertTrue(cairn.rule().startsWith("Cairn Goal\\u001b[31m\\u0007 x 'x' is not a number"), cairn.rule());
        MapFileException first = fails(write("esc4.map", esc + "\n"), Long.MAX_VALUE);
        assertTrue(first.rule().startsWith("the first line is '\\u001b[31m\\u0007'"), first.rule());
        MapFileException count = fails(write("esc5.map", "2D-Map\nDATA\n1 2 " + esc + "\n"), Long.MAX_VALUE);
        assertTrue(count.rule().startsWith("'1 2 \\u001b[31m\\u0007' has 3 values"), count.rule());
    }

    @Test
    void aMapTooLargeForTheHeapIsRefusedFromItsHeaderNamingXmx() throws IOException {
        Path file = write("huge.map", "2D-Map\nNumPoints: 10000000\nNumLines: 5\nDATA\n1 2\n");
        MapFileException e = fails(file, 1L << 30);
        assertEquals(3, e.line());
        assertTrue(e.rule().contains("the header says the map holds 10000000 points and 5 lines"), e.rule());
        assertTrue(e.rule().contains("but this Java may use 1024 MB"), e.rule());
        assertTrue(e.rule().contains("-Xmx") && e.rule().contains("ROBOSIM_JAVA_OPTS=-Xmx3g bin/robosim"), e.rule());
        // the same map is read where the heap suffices
        assertEquals(1, MapReader.read(file, 4L << 30).pointCount());
    }

    @Test
    void aHeaderThatUnderstatesIsCaughtByTheCount() throws IOException {
        StringBuilder text = new StringBuilder("2D-Map\nNumPoints: 1\nDATA\n");
        for (int i = 0; i < MapMemory.CHECK_EVERY; i++) {
            text.append(i).append(" 0\n");
        }
        long heap = MapMemory.need(MapMemory.CHECK_EVERY - 1, 0);
        MapFileException e = fails(write("liar.map", text.toString()), heap);
        assertEquals(3 + MapMemory.CHECK_EVERY, e.line());
        assertTrue(e.rule().startsWith("the map holds at least " + MapMemory.CHECK_EVERY + " points"), e.rule());
    }

    @Test
    void lineEndsCountAsAnEditorCountsThem() throws IOException {
        MapFile map = MapReader.read(write("ends.map", "2D-Map\r\nDATA\r\n1 2\r\r\n3 4\r5 6\n\n7 8"), Long.MAX_VALUE);
        assertEquals(java.util.List.of(3, 5, 6, 8), java.util.Arrays.stream(map.pointLines()).boxed().toList());
    }
}
