package robosim.env.world.maze;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/**
 * Writes a {@link Maze} as a RoboSim world file: the cell size as the world property
 * {@value #CELL_SIZE_PROPERTY}, walls on the grid lines (100 mm thick, merged into long runs),
 * boundary walls, robots in the cells nearest the start corner, and the gold, glowing with heat, in
 * the cell farthest from the start by path.
 */
public final class MazeWorldWriter {
    /** The world property that gives the maze's cell size, mm, to the robots in their welcome. */
    public static final String CELL_SIZE_PROPERTY = "cellSize";
    /** The gold's heat intensity, as felt 1 m away. */
    public static final double GOLD_INTENSITY = 50;

    private MazeWorldWriter() {
    }

    /**
     * @param maze       the maze
     * @param name       the world's name
     * @param cellSize   mm per cell, at least 1000 so a Pioneer can turn in a cell
     * @param robots     how many robots (r1, r2, ...) to place, at most one per cell
     * @param paramsPath the robots' parameter file, as the world file should name it
     * @return the world file's text
     */
    public static String write(Maze maze, String name, int cellSize, int robots, String paramsPath) {
        if (cellSize < 1000) {
            throw new IllegalArgumentException(cellSize + " was supplied for cellSize: at least 1000 mm, so a Pioneer can turn in a cell");
        }
        int cells = maze.width() * maze.height();
        if (robots < 1 || robots >= cells) {
            throw new IllegalArgumentException(robots + " was supplied for robots: from 1 to " + (cells - 1)
                    + " fit in a maze of " + cells + " cells with the gold");
        }
        StringBuilder xml = new StringBuilder();
        xml.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        xml.append(String.format(Locale.ROOT, "<!-- a %d x %d perfect maze of %d mm cells, written by bin/robosim maze -->%n",
                maze.width(), maze.height(), cellSize));
        xml.append(String.format(Locale.ROOT, "<world name=\"%s\" width=\"%d\" height=\"%d\" stepMs=\"100\" boundary=\"true\">%n",
                name, maze.width() * cellSize, maze.height() * cellSize));
        // robot programs learn the grid from the world, not from their command line
        xml.append(String.format(Locale.ROOT, "  <property name=\"%s\" value=\"%d\"/>%n", CELL_SIZE_PROPERTY, cellSize));
        for (int[] w : walls(maze)) {
            xml.append(String.format(Locale.ROOT, "  <wall x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\"/>%n",
                    w[0] * cellSize, w[1] * cellSize, w[2] * cellSize, w[3] * cellSize));
        }
        int[][] dist = maze.distancesFrom(0, 0);
        List<int[]> byDistance = new ArrayList<>();
        for (int x = 0; x < maze.width(); x++) {
            for (int y = 0; y < maze.height(); y++) {
                byDistance.add(new int[] {x, y, dist[x][y]});
            }
        }
        byDistance.sort(Comparator.<int[]>comparingInt(c -> c[2]).thenComparingInt(c -> c[0]).thenComparingInt(c -> c[1]));
        for (int k = 0; k < robots; k++) {
            int[] c = byDistance.get(k);
            xml.append(String.format(Locale.ROOT,
                    "  <robot name=\"r%d\" type=\"pioneer\" x=\"%d\" y=\"%d\" th=\"%d\" params=\"%s\"/>%n",
                    k + 1, c[0] * cellSize + cellSize / 2, c[1] * cellSize + cellSize / 2, openHeading(maze, c[0], c[1]),
                    paramsPath));
        }
        int[] gold = byDistance.get(byDistance.size() - 1);
        xml.append(String.format(Locale.ROOT, "  <gold x=\"%d\" y=\"%d\" intensity=\"%.0f\"/>%n",
                gold[0] * cellSize + cellSize / 2, gold[1] * cellSize + cellSize / 2, GOLD_INTENSITY));
        xml.append("</world>\n");
        return xml.toString();
    }

    /** Faces the robot down an open side of its cell, so it can start driving. */
    private static int openHeading(Maze maze, int x, int y) {
        for (int d = 0; d < 4; d++) {
            if (maze.open(x, y, d)) {
                return d * 90;
            }
        }
        return 0;
    }

    /** The inner walls as grid-line runs {x1, y1, x2, y2} in cells, merged where they continue. */
    static List<int[]> walls(Maze maze) {
        List<int[]> out = new ArrayList<>();
        // vertical lines x = 1 .. width-1: a wall segment between (x-1, y) and (x, y) when closed
        for (int x = 1; x < maze.width(); x++) {
            int start = -1;
            for (int y = 0; y <= maze.height(); y++) {
                boolean closed = y < maze.height() && !maze.open(x - 1, y, 0);
                if (closed && start < 0) {
                    start = y;
                } else if (!closed && start >= 0) {
                    out.add(new int[] {x, start, x, y});
                    start = -1;
                }
            }
        }
        for (int y = 1; y < maze.height(); y++) {
            int start = -1;
            for (int x = 0; x <= maze.width(); x++) {
                boolean closed = x < maze.width() && !maze.open(x, y - 1, 1);
                if (closed && start < 0) {
                    start = x;
                } else if (!closed && start >= 0) {
                    out.add(new int[] {start, y, x, y});
                    start = -1;
                }
            }
        }
        return out;
    }
}
