package robosim.env.world.map;

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
}
