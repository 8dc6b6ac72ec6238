package robosim.env.world.map;

import java.util.Arrays;
import java.util.List;
import robosim.env.world.Obstacle;
import robosim.map.Coordinates;

/**
 * Turns a map's points into obstacles: each point is a square of the map's resolution; points that
 * follow each other along a row (the same y, at most one side apart), or else along a column, form
 * a run; and runs that climb like the steps of a straight wall at a slant are joined into one
 * convex obstacle covering their squares ({@link Staircases}). A scanned wall of a thousand points
 * is then one obstacle of a few edges instead of four thousand edges, which is what the
 * GeometryClient's sensor and collision queries, and its indexes, pay for. A point that lines up
 * with no other stays a square.
 */
final class PointMerger {
    private final Coordinates points;
    private final double side;
    private final double height;

    PointMerger(double[] xy, int[] lines, double side, double height) {
        this(Coordinates.of(2, xy, lines), side, height);
    }

    /**
     * @param points the points, as read
     * @param side   the side of a point's square, mm
     * @param height the obstacles' height, mm
     */
    PointMerger(Coordinates points, double side, double height) {
        this.points = points;
        this.side = side;
        this.height = height;
    }

    /** @return the obstacles: those of row runs (lone points among them) first, then those of column runs */
    List<Obstacle> merge() {
        int n = points.count();
        int[] byRow = new int[n];
        for (int i = 0; i < n; i++) {
            byRow[i] = i;
        }
        IndexSort.sort(byRow, points::get, 1, 0);
        boolean[] used = new boolean[n];
        Staircases rows = new Staircases(side, height, false);
        runs(byRow, n, 1, 0, used, rows, null);
        int left = 0;
        for (int k = 0; k < n; k++) {
            if (!used[byRow[k]]) {
                byRow[left++] = byRow[k];
            }
        }
        int[] byColumn = Arrays.copyOf(byRow, left);
        byRow = null; // the column sort's buffer may take its place
        IndexSort.sort(byColumn, points::get, 0, 1);
        Staircases columns = new Staircases(side, height, true);
        // lone points join the rows: a 45-degree wall is a staircase of single points
        runs(byColumn, left, 0, 1, used, columns, rows);
        List<Obstacle> out = rows.obstacles();
        out.addAll(columns.obstacles());
        return out;
    }

    /**
     * Walks points sorted by {@code major} then {@code minor} coordinate, gathering runs along
     * {@code minor}; a run of two or more goes to {@code into}, and with {@code singles} given a
     * lone point goes there.
     */
    private void runs(int[] order, int count, int major, int minor, boolean[] used, Staircases into,
                      Staircases singles) {
        int start = 0;
        for (int k = 1; k <= count; k++) {
            boolean continues = k < count
                    && points.get(order[k], major) == points.get(order[k - 1], major)
                    && points.get(order[k], minor) - points.get(order[k - 1], minor) <= side;
            if (continues) {
                continue;
            }
            if (k - start >= 2 || singles != null) {
                int first = order[start];
                int last = order[k - 1];
                int line = Integer.MAX_VALUE;
                for (int m = start; m < k; m++) {
                    used[order[m]] = true;
                    line = Math.min(line, points.line(order[m]));
                }
                Staircases to = k - start >= 2 ? into : singles;
                // a single goes to the rows, where its row is its major coordinate y
                double at = to == into ? points.get(first, major) : points.get(first, 1);
                double from = to == into ? points.get(first, minor) : points.get(first, 0);
                double end = to == into ? points.get(last, minor) : points.get(first, 0);
                to.add(at, from, end, line);
            }
            start = k;
        }
    }
}
