package robosim.env.world.maze;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The maze generator: every maze is perfect (one path between any two cells), a seed always gives
 * the same maze, and the grid's edges and sizes are kept.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class MazeTest {
    private static final int EAST = 0;
    private static final int NORTH = 1;
    private static final int WEST = 2;
    private static final int SOUTH = 3;

    /** Open inner walls, each counted once (from its west or south cell). */
    private static int openWalls(Maze m) {
        int open = 0;
        for (int x = 0; x < m.width(); x++) {
            for (int y = 0; y < m.height(); y++) {
                open += m.open(x, y, EAST) ? 1 : 0;
                open += m.open(x, y, NORTH) ? 1 : 0;
            }
        }
        return open;
    }

    /** The closed inner walls as unit segments: "V x y" on the line x between rows y and y + 1, "H x y" likewise. */
    private static Set<String> closedInnerWalls(Maze m) {
        Set<String> closed = new TreeSet<>();
        for (int x = 1; x < m.width(); x++) {
            for (int y = 0; y < m.height(); y++) {
                if (!m.open(x - 1, y, EAST)) {
                    closed.add("V " + x + " " + y);
                }
            }
        }
        for (int y = 1; y < m.height(); y++) {
            for (int x = 0; x < m.width(); x++) {
                if (!m.open(x, y - 1, NORTH)) {
                    closed.add("H " + x + " " + y);
                }
            }
        }
        return closed;
    }

    /** Every cell's open sides, as one string: what tells two mazes apart. */
    private static String layout(Maze m) {
        StringBuilder s = new StringBuilder();
        for (int y = m.height() - 1; y >= 0; y--) {
            for (int x = 0; x < m.width(); x++) {
                int mask = 0;
                for (int d = 0; d < 4; d++) {
                    mask |= m.open(x, y, d) ? 1 << d : 0;
                }
                s.append(Integer.toHexString(mask));
            }
            s.append('\n');
        }
        return s.toString();
    }

    @ParameterizedTest
    @CsvSource({"1, 1, 7", "2, 2, 1", "5, 5, 11", "10, 10, 12", "20, 20, 13", "7, 3, 1", "1, 9, 2", "100, 100, 5"})
    void everyCellIsReachableFromTheStartCorner(int width, int height, long seed) {
        int[][] dist = Maze.generate(width, height, seed).distancesFrom(0, 0);
        for (int x = 0; x < width; x++) {
            for (int y = 0; y < height; y++) {
                assertTrue(dist[x][y] >= 0, "cell (" + x + ", " + y + ") is unreachable");
            }
        }
    }

    /** Connected with one wall fewer opened than there are cells: a tree, so exactly one path between two cells. */
    @ParameterizedTest
    @CsvSource({"1, 1, 7", "2, 2, 1", "5, 5, 11", "10, 10, 12", "20, 20, 13", "7, 3, 1", "1, 9, 2", "100, 100, 5"})
    void aPerfectMazeOpensOneWallFewerThanItHasCells(int width, int height, long seed) {
        assertEquals(width * height - 1, openWalls(Maze.generate(width, height, seed)));
    }

    @ParameterizedTest
    @CsvSource({"5, 5, 11", "10, 10, 12", "7, 3, 1"})
    void neighboursAcrossAnOpenWallAreOneStepApartFromTheStart(int width, int height, long seed) {
        Maze m = Maze.generate(width, height, seed);
        int[][] dist = m.distancesFrom(0, 0);
        for (int x = 0; x < width; x++) {
            for (int y = 0; y < height; y++) {
                if (m.open(x, y, EAST)) {
                    assertEquals(1, Math.abs(dist[x][y] - dist[x + 1][y]), "(" + x + ", " + y + ") east");
                }
                if (m.open(x, y, NORTH)) {
                    assertEquals(1, Math.abs(dist[x][y] - dist[x][y + 1]), "(" + x + ", " + y + ") north");
                }
            }
        }
    }

    @Test
    void everyOpenWallIsOpenFromBothSides() {
        Maze m = Maze.generate(9, 6, 3);
        for (int x = 0; x < 9; x++) {
            for (int y = 0; y < 6; y++) {
                if (x + 1 < 9) {
                    assertEquals(m.open(x, y, EAST), m.open(x + 1, y, WEST), "(" + x + ", " + y + ") east");
                }
                if (y + 1 < 6) {
                    assertEquals(m.open(x, y, NORTH), m.open(x, y + 1, SOUTH), "(" + x + ", " + y + ") north");
                }
            }
        }
    }

    @Test
    void theOuterBoundaryIsClosedAllRound() {
        Maze m = Maze.generate(9, 6, 3);
        for (int y = 0; y < 6; y++) {
            assertFalse(m.open(0, y, WEST), "west edge, row " + y);
            assertFalse(m.open(8, y, EAST), "east edge, row " + y);
        }
        for (int x = 0; x < 9; x++) {
            assertFalse(m.open(x, 0, SOUTH), "south edge, column " + x);
            assertFalse(m.open(x, 5, NORTH), "north edge, column " + x);
        }
    }

    @Test
    void theSameSeedGivesTheSameMaze() {
        assertEquals(layout(Maze.generate(12, 8, 42)), layout(Maze.generate(12, 8, 42)));
    }

    @Test
    void differentSeedsGiveDifferentMazes() {
        String one = layout(Maze.generate(8, 8, 1));
        String two = layout(Maze.generate(8, 8, 2));
        String three = layout(Maze.generate(8, 8, 3));
        assertNotEquals(one, two);
        assertNotEquals(one, three);
        assertNotEquals(two, three);
    }

    /**
     * The shipped maze-small.xml was written by {@code bin/robosim maze} for seed 11: the generator
     * must still carve that maze from that seed, or the shipped worlds no longer name their seeds.
     */
    @Test
    void seed11StillCarvesTheShippedSmallMaze() throws IOException {
        String xml = Files.readString(root().resolve("testLoadFiles/environment/maze-small.xml"));
        assertTrue(xml.contains("name=\"maze-5x5-11\""), "the shipped file is the 5 x 5 maze of seed 11");
        Set<String> shipped = new TreeSet<>();
        Matcher w = Pattern.compile("<wall x1=\"(\\d+)\" y1=\"(\\d+)\" x2=\"(\\d+)\" y2=\"(\\d+)\"/>").matcher(xml);
        while (w.find()) {
            int x1 = Integer.parseInt(w.group(1)) / 1500;
            int y1 = Integer.parseInt(w.group(2)) / 1500;
            int x2 = Integer.parseInt(w.group(3)) / 1500;
            int y2 = Integer.parseInt(w.group(4)) / 1500;
            if (x1 == x2) {
                for (int y = y1; y < y2; y++) {
                    shipped.add("V " + x1 + " " + y);
                }
            } else {
                for (int x = x1; x < x2; x++) {
                    shipped.add("H " + x + " " + y1);
                }
            }
        }
        assertEquals(shipped, closedInnerWalls(Maze.generate(5, 5, 11)));
    }

    /**
     * Path lengths from (0, 0) in the shipped small maze (seed 11), as the world writer reads them
     * to place the gold: 18 cells to (2, 2), where maze-small.xml has its gold, and to (0, 4).
     */
    @Test
    void distancesFromTheStartOfTheSeed11MazeFollowItsOnlyPaths() {
        int[][] byColumn = {
            {0, 15, 16, 17, 18},
            {1, 14, 13, 12, 11},
            {2, 15, 18, 9, 10},
            {3, 16, 17, 8, 11},
            {4, 5, 6, 7, 12},
        };
        assertArrayEquals(byColumn, Maze.generate(5, 5, 11).distancesFrom(0, 0));
    }

    @Test
    void distancesFromACellCountZeroThereAndGrowAwayFromIt() {
        int[][] dist = Maze.generate(5, 5, 11).distancesFrom(2, 2);
        assertEquals(0, dist[2][2]);
        assertEquals(18, dist[0][0], "the same path as from (0, 0) to (2, 2)");
    }

    @Test
    void aOneCellMazeHasNoOpenSide() {
        Maze m = Maze.generate(1, 1, 7);
        assertEquals(1, m.width());
        assertEquals(1, m.height());
        for (int d = 0; d < 4; d++) {
            assertFalse(m.open(0, 0, d), "side " + d);
        }
        assertArrayEquals(new int[][] {{0}}, m.distancesFrom(0, 0));
    }

    @Test
    void aOneRowMazeIsACorridorOpenBetweenEveryTwoNeighbours() {
        Maze m = Maze.generate(6, 1, 99);
        for (int x = 0; x < 5; x++) {
            assertTrue(m.open(x, 0, EAST), "east of column " + x);
        }
        assertArrayEquals(new int[][] {{2}, {1}, {0}, {1}, {2}, {3}}, m.distancesFrom(2, 0));
    }

    @Test
    void aOneColumnMazeIsACorridorOpenBetweenEveryTwoNeighbours() {
        Maze m = Maze.generate(1, 4, 99);
        for (int y = 0; y < 3; y++) {
            assertTrue(m.open(0, y, NORTH), "north of row " + y);
        }
        assertArrayEquals(new int[][] {{3, 2, 1, 0}}, m.distancesFrom(0, 3));
    }

    @Test
    void theSizeIsKept() {
        Maze m = Maze.generate(7, 3, 1);
        assertEquals(7, m.width());
        assertEquals(3, m.height());
    }

    @ParameterizedTest
    @CsvSource({"100, 100", "10000, 1", "1, 10000"})
    void upToTenThousandCellsAreAccepted(int width, int height) {
        Maze m = Maze.generate(width, height, 1);
        assertEquals(width * height - 1, openWalls(m));
    }

    @ParameterizedTest
    @CsvSource({"0, 5", "5, 0", "-1, 3", "100, 101", "10001, 1", "100000, 100000"})
    void aSizeOutsideTheLimitsIsRejectedNamingIt(int width, int height) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Maze.generate(width, height, 1));
        assertEquals(width + " x " + height + " was supplied for the maze's cells: each side must be at least 1"
                + " and the maze at most 10000 cells", e.getMessage());
    }

    @ParameterizedTest
    @ValueSource(ints = {-1, 4, 90})
    void aDirectionOutside0To3IsRejectedNamingIt(int dir) {
        Maze m = Maze.generate(3, 3, 1);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> m.open(1, 1, dir));
        assertEquals(dir + " was supplied for dir: it must be 0 to 3", e.getMessage());
    }

    private static Path root() {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        assertTrue(p != null, "no testLoadFiles above " + System.getProperty("robosim.root", ""));
        return p;
    }
}
