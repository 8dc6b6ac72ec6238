package robosim.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Broken map files: each error names the file, the line and the rule. */
class MapReaderErrorTest {
    @TempDir
    Path dir;

    private MapFileException fails(String text, int line, String words) throws IOException {
        Path file = dir.resolve("broken.map");
        Files.writeString(file, text);
        MapFileException e = assertThrows(MapFileException.class, () -> MapReader.read(file));
        assertEquals(line, e.line(), e.getMessage());
        assertTrue(e.getMessage().startsWith(file + ":" + line + ": "), e.getMessage());
        assertTrue(e.rule().contains(words), e.getMessage());
        return e;
    }

    @Test
    void aMissingHeaderIsNamed() throws IOException {
        fails("LINES\n0 0 10 10\n", 1, "the first line is 'LINES' but a map file starts with 2D-Map");
    }

    @Test
    void aLineWithThreeValues() throws IOException {
        fails("2D-Map\nLINES\n0 0 10 10\n0 0 10\n", 4, "'0 0 10' has 3 values but a line of LINES holds x1 y1 x2 y2");
    }

    @Test
    void aPointWithOneValue() throws IOException {
        fails("2D-Map\nDATA\n5\n", 3, "'5' has 1 value but a point of DATA holds x y");
    }

    @ParameterizedTest
    @CsvSource({
        "12a, coordinate '12a' is not a number",
        "NaN, coordinate 'NaN' is not a number",
        "2e9, coordinate 2e9 must be from -1000000000 to 1000000000",
        "-2e8, coordinate -2e8 must be from -100000000 to 100000000"})
    void aBadCoordinate(String value, String words) throws IOException {
        fails("2D-Map\nDATA\n1 2\n" + value + " 7\n", 4, words);
    }

    @Test
    void aBadResolution() throws IOException {
        fails("2D-Map\nResolution: fine\nDATA\n", 2, "Resolution 'fine' is not a number");
    }

    @Test
    void aHeaderLineWithoutAColon() throws IOException {
        fails("2D-Map\nMinPos 0 0\nDATA\n", 2, "'MinPos 0 0' is neither a 'Key: values' header line nor LINES or DATA");
    }

    @Test
    void aCornerWithOneValue() throws IOException {
        fails("2D-Map\nLineMaxPos: 100\nDATA\n", 2, "LineMaxPos has 1 value but holds x y");
    }

    @Test
    void aCornerThatIsNoNumber() throws IOException {
        fails("2D-Map\nMinPos: 0 north\nDATA\n", 2, "MinPos y 'north' is not a number");
    }

    @Test
    void aCairnWithTooFewValues() throws IOException {
        fails("2D-Map\nCairn: RobotHome 100 200\n", 2, "a Cairn has 3 values but needs at least 7");
    }

    @Test
    void aForbiddenAreaWithoutCorners() throws IOException {
        fails("2D-Map\nCairn: ForbiddenArea 0 0 0 \"\" ICON \"\"\n", 2,
                "a Cairn ForbiddenArea has 7 values but needs 11");
    }

    @Test
    void anUnclosedQuote() throws IOException {
        fails("2D-Map\nCairn: Goal 0 0 0 \"\" ICON \"open\n", 2, "a quoted string that is not closed");
    }

    @Test
    void aMissingFileIsNamed() {
        Path file = dir.resolve("none.map");
        MapFileException e = assertThrows(MapFileException.class, () -> MapReader.read(file));
        assertEquals(file + ": no such map file", e.getMessage());
    }
}
