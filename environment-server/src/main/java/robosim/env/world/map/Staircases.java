package robosim.env.world.map;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import robosim.env.world.Obstacle;

/**
 * Joins runs of points that climb row by row (or column by column) like the steps of a straight
 * wall at a slant: a run whose first point lies one side past the end of the run below it (or whose
 * last point lies one side before its start) continues it, as long as every step stays within one
 * side of the straight line from the first step's start to the last step's end. The steps become
 * one convex obstacle, the hull of their squares, which covers them and strays at most about one
 * side from them; a run that continues nothing stays the rectangle of its squares.
 *
 * <p>Runs are kept in (u, v) coordinates: u along the run, v across: x and y for rows, y and x for
 * columns.
 */
final class Staircases {
    private final double side;
    private final double height;
    private final boolean columns;
    /** Per run: v (its row or column), then its first and last u. */
    private double[] runs = new double[3 * 64];
    /** Per run: v and first u, for sorting. */
    private double[] keys = new double[2 * 64];
    private int[] lines = new int[64];
    private int size;

    /**
     * @param side    the side of a point's square, mm
     * @param height  the obstacles' height, mm
     * @param columns whether the runs are columns (u is y) rather than rows (u is x)
     */
    Staircases(double side, double height, boolean columns) {
        this.side = side;
        this.height = height;
        this.columns = columns;
    }

    /** Adds a run of points from u = {@code from} to {@code to} at v = {@code at}. */
    void add(double at, double from, double to, int line) {
        if (size == lines.length) {
            runs = Arrays.copyOf(runs, runs.length * 2);
            keys = Arrays.copyOf(keys, keys.length * 2);
            lines = Arrays.copyOf(lines, lines.length * 2);
        }
        runs[3 * size] = at;
        runs[3 * size + 1] = from;
        runs[3 * size + 2] = to;
        keys[2 * size] = at;
        keys[2 * size + 1] = from;
        lines[size++] = line;
    }

    /** @return the obstacles: each staircase, lowest first, as the hull of its squares */
    List<Obstacle> obstacles() {
        int[] order = new int[size];
        for (int i = 0; i < size; i++) {
            order[i] = i;
        }
        IndexSort.sort(order, keys, 0);
        // sorted runs: v, first u, last u
        double[] sorted = new double[3 * size];
        int[] sortedLines = new int[size];
        for (int k = 0; k < size; k++) {
            System.arraycopy(runs, 3 * order[k], sorted, 3 * k, 3);
            sortedLines[k] = lines[order[k]];
        }
        boolean[] used = new boolean[size];
        List<Obstacle> out = new ArrayList<>();
        List<Integer> chain = new ArrayList<>();
        for (int k = 0; k < size; k++) {
            if (used[k]) {
                continue;
            }
            chain.clear();
            chain.add(k);
            used[k] = true;
            int direction = 0;
            int last = k;
            while (true) {
                double v = sorted[3 * last] + side;
                int next = -1;
                if (direction >= 0) {
                    int j = find(sorted, v, 1, sorted[3 * last + 2] + side);
                    next = j >= 0 && !used[j] ? j : -1;
                    direction = next >= 0 ? 1 : direction;
                }
                if (next < 0 && direction <= 0) {
                    int j = find(sorted, v, 2, sorted[3 * last + 1] - side);
                    next = j >= 0 && !used[j] ? j : -1;
                    direction = next >= 0 ? -1 : direction;
                }
                if (next < 0 || !straight(sorted, chain, next, direction)) {
                    break;
                }
                chain.add(next);
                used[next] = true;
                last = next;
            }
            int line = Integer.MAX_VALUE;
            for (int c : chain) {
                line = Math.min(line, sortedLines[c]);
            }
            out.add(new Obstacle(hull(sorted, chain), height, line));
        }
        return out;
    }

    /** @return the sorted run at v whose first (field 1) or last (field 2) u is {@code u}, or -1 */
    private int find(double[] sorted, double v, int field, double u) {
        int lo = 0;
        int hi = size - 1;
        // runs are sorted by v, then by first u; runs of one v do not overlap, so also by last u
        while (lo <= hi) {
            int mid = (lo + hi) >>> 1;
            double mv = sorted[3 * mid];
            double mu = sorted[3 * mid + field];
            if (mv < v || mv == v && mu < u) {
                lo = mid + 1;
            } else if (mv > v || mu > u) {
                hi = mid - 1;
            } else {
                return mid;
            }
        }
        return -1;
    }

    /** @return whether every step of the chain with {@code next} added lies within one side of its line */
    private boolean straight(double[] sorted, List<Integer> chain, int next, int direction) {
        int first = chain.get(0);
        double u0 = sorted[3 * first + (direction > 0 ? 1 : 2)];
        double v0 = sorted[3 * first];
        double u1 = sorted[3 * next + (direction > 0 ? 2 : 1)];
        double slope = (sorted[3 * next] - v0) / (u1 - u0);
        for (int k = 0; k <= chain.size(); k++) {
            int c = k < chain.size() ? chain.get(k) : next;
            double v = sorted[3 * c];
            for (int end = 1; end <= 2; end++) {
                double expected = v0 + (sorted[3 * c + end] - u0) * slope;
                if (Math.abs(v - expected) > side) {
                    return false;
                }
            }
        }
        return true;
    }

    /** @return the counter-clockwise hull, x, y, of the chain's squares (a rectangle for one run) */
    private double[] hull(double[] sorted, List<Integer> chain) {
        double h = side / 2;
        double[] uv = new double[8 * chain.size()];
        int n = 0;
        for (int c : chain) {
            double v = sorted[3 * c];
            double from = sorted[3 * c + 1];
            double to = sorted[3 * c + 2];
            double[] corners = {from - h, v - h, to + h, v - h, to + h, v + h, from - h, v + h};
            System.arraycopy(corners, 0, uv, n, 8);
            n += 8;
        }
        double[] ring = ConvexHull.of(uv);
        if (!columns) {
            return ring;
        }
        // (u, v) is (y, x): swapping the axes mirrors the ring, so it is walked backwards
        double[] xy = new double[ring.length];
        int points = ring.length / 2;
        for (int i = 0; i < points; i++) {
            int from = (points - i) % points;
            xy[2 * i] = ring[2 * from + 1];
            xy[2 * i + 1] = ring[2 * from];
        }
        return xy;
    }
}
