package robosim.env.world.map;

import java.util.Arrays;
import java.util.List;
import robosim.env.world.Obstacle;

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
    private final double[] xy;
    private final int[] lines;
    private final double side;
    private final double height;

    PointMerger(double[] xy, int[] lines, double side, double height) {
        this.xy = xy;
        this.lines = lines;
        this.side = side;
        this.height = height;
    }

    /** @return the obstacles: those of row runs (lone points among them) first, then those of column runs */
    List<Obstacle> merge() {
        int n = lines.length;
        int[] byRow = new int[n];
        for (int i = 0; i < n; i++) {
            byRow[i] = i;
        }
        IndexSort.sort(byRow, xy, 1);
        boolean[] used = new boolean[n];
        Staircases rows = new Staircases(side, height, false);
        runs(byRow, n, 1, 0, used, rows, null);
        int[] byColumn = new int[n];
        int left = 0;
        for (int i : byRow) {
            if (!used[i]) {
                byColumn[left++] = i;
            }
        }
        byColumn = Arrays.copyOf(byColumn, left);
        IndexSort.sort(byColumn, xy, 0);
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
                    && xy[2 * order[k] + major] == xy[2 * order[k - 1] + major]
                    && xy[2 * order[k] + minor] - xy[2 * order[k - 1] + minor] <= side;
            if (continues) {
                continue;
            }
            if (k - start >= 2 || singles != null) {
                int first = order[start];
                int last = order[k - 1];
                int line = Integer.MAX_VALUE;
                for (int m = start; m < k; m++) {
                    used[order[m]] = true;
                    line = Math.min(line, lines[order[m]]);
                }
                Staircases to = k - start >= 2 ? into : singles;
                // a single goes to the rows, where its row is its major coordinate y
                double at = to == into ? xy[2 * first + major] : xy[2 * first + 1];
                double from = to == into ? xy[2 * first + minor] : xy[2 * first];
                double end = to == into ? xy[2 * last + minor] : xy[2 * first];
                to.add(at, from, end, line);
            }
            start = k;
        }
    }
}
