package robosim.map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Reading the lines, points and cairns of a map file. */
class MapReaderTest {
    /** A small map: a 8 m x 6 m room around the origin, four points in a row and one alone. */
    static final String LAB = """
            2D-Map
            MinPos: 2000 0
            MaxPos: 3000 3000
            NumPoints: 5
            LineMinPos: -3000 -2000
            LineMaxPos: 5000 4000
            NumLines: 4
            Resolution: 20
            Cairn: RobotHome 1000 1000 90 "" ICON "Home"
            Cairn: Goal 3000 2000 0 "" ICON "G1"
            Cairn: ForbiddenArea 0 0 0.000000 "" ICON "keep out" -2500 2500 -1500 3500
            Cairn: ForbiddenLine 0 0 0.000000 "" ICON "" 0 -1500 4000 -1500
            LINES
            -3000 -2000 5000 -2000
            5000 -2000 5000 4000
            5000 4000 -3000 4000
            -3000 4000 -3000 -2000
            DATA
            2000 0
            2020 0
            2040 0
            2060 0
            3000 3000
            """;

    @TempDir
    Path dir;

    private MapFile read(String text) throws IOException {
        Path file = dir.resolve("lab.map");
        Files.writeString(file, text);
        return MapReader.read(file);
    }

    @Test
    void readsTheLinesWithTheirFileLines() throws IOException {
        MapFile map = read(LAB);
        assertEquals(4, map.lineCount());
        assertArrayEquals(new double[] {-3000, -2000, 5000, -2000}, java.util.Arrays.copyOf(map.lines(), 4));
        assertArrayEquals(new int[] {14, 15, 16, 17}, map.lineLines());
    }

    @Test
    void readsThePointsWithTheirFileLines() throws IOException {
        MapFile map = read(LAB);
        assertEquals(5, map.pointCount());
        assertArrayEquals(new double[] {2000, 0, 2020, 0, 2040, 0, 2060, 0, 3000, 3000}, map.points());
        assertArrayEquals(new int[] {19, 20, 21, 22, 23}, map.pointLines());
        assertEquals(20, map.resolution());
    }

    @Test
    void readsTheCairnsWithTheirLabelsAndCorners() throws IOException {
        List<Cairn> cairns = read(LAB).cairns();
        assertEquals(new Cairn("RobotHome", 1000, 1000, 90, "Home", new double[0], 9), cairns.get(0));
        assertEquals(new Cairn("ForbiddenArea", 0, 0, 0, "keep out", new double[] {-2500, 2500, -1500, 3500}, 11),
                cairns.get(2));
        assertEquals(4, cairns.size());
    }

    @Test
    void dataBeforeLinesAndExHeaderAreRead() throws IOException {
        MapFile map = read("2D-Map-Ex2\nDATA\n10 20\nLINES\n0 0 100 0\n\nLaser_DATA\n30 40\n");
        assertArrayEquals(new double[] {10, 20, 30, 40}, map.points());
        assertArrayEquals(new double[] {0, 0, 100, 0}, map.lines());
        assertArrayEquals(new int[] {3, 8}, map.pointLines());
    }

    @Test
    void countsThatDisagreeWithTheHeaderAreOnlyAWarning() throws IOException {
        MapFile map = read("2D-Map\nNumPoints: 7\nNumLines: 0\nLINES\n0 0 100 0\nDATA\n5 5\n");
        assertEquals(1, map.lineCount());
        assertEquals(1, map.pointCount());
    }

    @Test
    void unknownHeaderKeysAreSkipped() throws IOException {
        MapFile map = read("2D-Map\nOriginLatLongAlt: 42.8 -71.5 72\nMapInfo: GoalType Name=Goal\nDATA\n1 2\n");
        assertEquals(1, map.pointCount());
    }

    @Test
    void readsTheHeadersCornersCountsAndMapInfo() throws IOException {
        MapHeader header = read(LAB.replace("Resolution: 20", "Resolution: 20\nMapInfo: GoalType Name=Goal\nMapInfo: Dock")).header();
        assertEquals(new MapHeader.Position(2000, 0), header.minPos());
        assertEquals(new MapHeader.Position(3000, 3000), header.maxPos());
        assertEquals(new MapHeader.Position(-3000, -2000), header.lineMinPos());
        assertEquals(new MapHeader.Position(5000, 4000), header.lineMaxPos());
        assertEquals(5, header.numPoints());
        assertEquals(4, header.numLines());
        assertEquals(List.of("GoalType Name=Goal", "Dock"), header.mapInfo());
    }

    @Test
    void aMapWithoutCornersOrCountsSaysSo() throws IOException {
        assertEquals(MapHeader.EMPTY, read("2D-Map\nDATA\n1 2\n").header());
    }

    @Test
    void aCairnsDescriptionIsTheQuotedStringAfterItsNameElseTheOneAfterTh() throws IOException {
        List<Cairn> cairns = read("""
                2D-Map
                Cairn: Goal 1 2 3 "old" ICON "G" "new words"
                Cairn: GoalWithHeading 1 2 3 "only" ID=4 "H"
                Cairn: ForbiddenLine 0 0 0 "" ICON "" 0 0 10 10 "line words"
                DATA
                """).cairns();
        assertEquals(new Cairn("Goal", 1, 2, 3, "new words", "ICON", "G", new double[0], 2), cairns.get(0));
        assertEquals(new Cairn("GoalWithHeading", 1, 2, 3, "only", "ID=4", "H", new double[0], 3), cairns.get(1));
        assertEquals("line words", cairns.get(2).description());
    }
}
