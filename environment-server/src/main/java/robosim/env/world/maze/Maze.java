package robosim.env.world.maze;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * A perfect maze on a grid of cells (exactly one path between any two cells), carved by a seeded
 * depth-first search. Cell (0, 0) is the lower left; x grows right, y grows up.
 */
public final class Maze {
    private final int width;
    private final int height;
    /** openEast[x][y]: no wall between (x, y) and (x + 1, y). */
    private final boolean[][] openEast;
    /** openNorth[x][y]: no wall between (x, y) and (x, y + 1). */
    private final boolean[][] openNorth;

    private Maze(int width, int height) {
        this.width = width;
        this.height = height;
        this.openEast = new boolean[width][height];
        this.openNorth = new boolean[width][height];
    }

    /**
     * Carves a maze.
     *
     * @param width  cells across, at least 1
     * @param height cells up, at least 1
     * @param seed   the seed; the same seed gives the same maze
     * @return the maze
     */
    public static Maze generate(int width, int height, long seed) {
        if (width < 1 || height < 1 || (long) width * height > 10_000) {
            throw new IllegalArgumentException(width + " x " + height
                    + " was supplied for the maze's cells: each side must be at least 1 and the maze at most 10000 cells");
        }
        Maze m = new Maze(width, height);
        SplittableRandom random = new SplittableRandom(seed);
        boolean[][] seen = new boolean[width][height];
        ArrayDeque<int[]> stack = new ArrayDeque<>();
        stack.push(new int[] {0, 0});
        seen[0][0] = true;
        while (!stack.isEmpty()) {
            int[] c = stack.peek();
            List<int[]> next = new ArrayList<>(4);
            for (int[] d : DIRECTIONS) {
                int nx = c[0] + d[0];
                int ny = c[1] + d[1];
                if (nx >= 0 && ny >= 0 && nx < width && ny < height && !seen[nx][ny]) {
                    next.add(new int[] {nx, ny});
                }
            }
            if (next.isEmpty()) {
                stack.pop();
                continue;
            }
            int[] n = next.get(random.nextInt(next.size()));
            m.open(c[0], c[1], n[0], n[1]);
            seen[n[0]][n[1]] = true;
            stack.push(n);
        }
        return m;
    }

    /** East, north, west, south. */
    static final int[][] DIRECTIONS = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};

    private void open(int x1, int y1, int x2, int y2) {
        if (x2 == x1 + 1) {
            openEast[x1][y1] = true;
        } else if (x2 == x1 - 1) {
            openEast[x2][y2] = true;
        } else if (y2 == y1 + 1) {
            openNorth[x1][y1] = true;
        } else {
            openNorth[x2][y2] = true;
        }
    }

    /** @return cells across */
    public int width() {
        return width;
    }

    /** @return cells up */
    public int height() {
        return height;
    }

    /**
     * @param x   a cell's column
     * @param y   a cell's row
     * @param dir 0 east, 1 north, 2 west, 3 south
     * @return whether the cell is open towards that neighbour
     */
    public boolean open(int x, int y, int dir) {
        return switch (dir) {
            case 0 -> x + 1 < width && openEast[x][y];
            case 1 -> y + 1 < height && openNorth[x][y];
            case 2 -> x > 0 && openEast[x - 1][y];
            case 3 -> y > 0 && openNorth[x][y - 1];
            default -> throw new IllegalArgumentException(dir + " was supplied for dir: it must be 0 to 3");
        };
    }

    /**
     * Path lengths, in cells, from one cell to every cell.
     *
     * @param x the start's column
     * @param y the start's row
     * @return distance[x][y]
     */
    public int[][] distancesFrom(int x, int y) {
        int[][] dist = new int[width][height];
        for (int[] row : dist) {
            java.util.Arrays.fill(row, -1);
        }
        ArrayDeque<int[]> queue = new ArrayDeque<>();
        queue.add(new int[] {x, y});
        dist[x][y] = 0;
        while (!queue.isEmpty()) {
            int[] c = queue.poll();
            for (int d = 0; d < 4; d++) {
                if (open(c[0], c[1], d)) {
                    int nx = c[0] + DIRECTIONS[d][0];
                    int ny = c[1] + DIRECTIONS[d][1];
                    if (dist[nx][ny] < 0) {
                        dist[nx][ny] = dist[c[0]][c[1]] + 1;
                        queue.add(new int[] {nx, ny});
                    }
                }
            }
        }
        return dist;
    }
}
