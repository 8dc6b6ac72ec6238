package robosim.env.world.map;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import robosim.env.world.Obstacle;

/**
 * Turns a map's points into obstacles: each point is a square of the map's resolution, and points
 * that follow each other along a row (the same y, at most one side apart), or else along a column,
 * become one rectangle covering their squares. A scanned wall of a thousand points is then one
 * obstacle of four edges instead of four thousand edges, which is what the GeometryClient's
 * sensor and collision queries pay for. A point that lines up with no other stays a square.
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

    /** @return the obstacles: row runs first, then column runs and single squares */
    List<Obstacle> merge() {
        int n = lines.length;
        List<Obstacle> out = new ArrayList<>();
        int[] byRow = new int[n];
        for (int i = 0; i < n; i++) {
            byRow[i] = i;
        }
        IndexSort.sort(byRow, xy, 1);
        boolean[] used = new boolean[n];
        runs(byRow, byRow.length, 1, 0, used, out, false);
        int[] byColumn = new int[n];
        int left = 0;
        for (int i : byRow) {
            if (!used[i]) {
                byColumn[left++] = i;
            }
        }
        byColumn = Arrays.copyOf(byColumn, left);
        IndexSort.sort(byColumn, xy, 0);
        runs(byColumn, left, 0, 1, used, out, true);
        return out;
    }

    /**
     * Walks points sorted by {@code major} then {@code minor} coordinate, gathering runs along
     * {@code minor}; a run of two or more becomes a rectangle, and with {@code keepSingles} a lone
     * point becomes a square.
     */
    private void runs(int[] order, int count, int major, int minor, boolean[] used, List<Obstacle> out,
                      boolean keepSingles) {
        int start = 0;
        for (int k = 1; k <= count; k++) {
            boolean continues = k < count
                    && xy[2 * order[k] + major] == xy[2 * order[k - 1] + major]
                    && xy[2 * order[k] + minor] - xy[2 * order[k - 1] + minor] <= side;
            if (continues) {
                continue;
            }
            if (k - start >= 2 || keepSingles && k - start == 1) {
                int first = order[start];
                int last = order[k - 1];
                int line = Integer.MAX_VALUE;
                for (int m = start; m < k; m++) {
                    used[order[m]] = true;
                    line = Math.min(line, lines[order[m]]);
                }
                out.add(rectangle(xy[2 * first], xy[2 * first + 1], xy[2 * last], xy[2 * last + 1], line));
            }
            start = k;
        }
    }

    private Obstacle rectangle(double x0, double y0, double x1, double y1, int line) {
        double h = side / 2;
        return new Obstacle(new double[] {x0 - h, y0 - h, x1 + h, y0 - h, x1 + h, y1 + h, x0 - h, y1 + h},
                height, line);
    }
}
