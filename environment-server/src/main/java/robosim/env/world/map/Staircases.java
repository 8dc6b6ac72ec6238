package robosim.env.world.map;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import robosim.env.world.Obstacle;
import robosim.map.Coordinates;

/**
 * Joins runs of points that climb row by row (or column by column) like the steps of a straight
 * wall at a slant, or lie on each other like the rows of a wall scanned two points thick: a run in
 * the next row that starts within the run below it or one side past its end, and ends no sooner,
 * continues it (or the same leftwards), as long as all the steps stay within a band
 * {@value #BAND} sides wide about the straight line from the first step's start to the last step's
 * end. The steps become one convex obstacle, the hull of their squares, which covers them and
 * strays at most about {@value #BAND} sides from them; a run that continues nothing stays the
 * rectangle of its squares.
 *
 * <p>Runs are kept in (u, v) coordinates: u along the run, v across: x and y for rows, y and x for
 * columns.
 */
final class Staircases {
    private final double side;
    private final double height;
    private final boolean columns;
    /** Per run: v (its row or column), then its first and last u; and its file line. */
    private Coordinates runs = new Coordinates(3);
    private final double[] run = new double[3];
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
        run[0] = at;
        run[1] = from;
        run[2] = to;
        runs.add(run, 0, line);
        size++;
    }

    /** @return the obstacles: each staircase, lowest first, as the hull of its squares */
    List<Obstacle> obstacles() {
        int[] order = new int[size];
        for (int i = 0; i < size; i++) {
            order[i] = i;
        }
        IndexSort.sort(order, runs::get, 0, 1);
        // the runs in sorted order: v, first u, last u
        Sorted sorted = new Sorted(runs, order);
        boolean[] used = new boolean[size];
        List<Obstacle> out = new ArrayList<>();
        Chain chain = new Chain();
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
                double v = sorted.get(last, 0) + side;
                int next = -1;
                if (direction >= 0) {
                    next = rightOf(sorted, used, v, sorted.get(last, 1), sorted.get(last, 2));
                    direction = next >= 0 ? 1 : direction;
                }
                if (next < 0 && direction <= 0) {
                    next = leftOf(sorted, used, v, sorted.get(last, 1), sorted.get(last, 2));
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
            for (int i = 0; i < chain.size; i++) {
                line = Math.min(line, runs.line(order[chain.at[i]]));
            }
            out.add(new Obstacle(hull(sorted, chain), height, line));
        }
        runs = null; // done: the obstacles take the room
        return out;
    }

    /**
     * @return the first unused run at v that continues a run from {@code from} to {@code to}
     *         rightwards: it starts within it or one side past its end, and ends no sooner; or -1
     */
    private int rightOf(Sorted sorted, boolean[] used, double v, double from, double to) {
        for (int j = lowerBound(sorted, v, from, 1); j < size && sorted.get(j, 0) == v && sorted.get(j, 1) <= to + side;
             j++) {
            if (!used[j] && sorted.get(j, 2) >= to) {
                return j;
            }
        }
        return -1;
    }

    /**
     * @return the first unused run at v that continues a run from {@code from} to {@code to}
     *         leftwards: it ends within it or one side before its start, and starts no later; or -1
     */
    private int leftOf(Sorted sorted, boolean[] used, double v, double from, double to) {
        // runs of one v do not overlap, so sorted by first u they are sorted by last u too
        for (int j = lowerBound(sorted, v, from - side, 2); j < size && sorted.get(j, 0) == v && sorted.get(j, 2) <= to;
             j++) {
            if (!used[j] && sorted.get(j, 1) <= from) {
                return j;
            }
        }
        return -1;
    }

    /** @return the first sorted run at or after (v, u), comparing u with field 1 (first u) or 2 (last u) */
    private int lowerBound(Sorted sorted, double v, double u, int field) {
        int lo = 0;
        int hi = size;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            double mv = sorted.get(mid, 0);
            if (mv < v || mv == v && sorted.get(mid, field) < u) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    /**
     * @return whether the chain with {@code next} added stays a straight band: every run's ends lie
     *         within a strip {@value #BAND} sides wide about the line from the first run's start
     *         to the next run's end (a wall scanned one or two points thick)
     */
    private boolean straight(Sorted sorted, Chain chain, int next, int direction) {
        int first = chain.at[0];
        double u0 = sorted.get(first, (direction > 0 ? 1 : 2));
        double v0 = sorted.get(first, 0);
        double du = sorted.get(next, (direction > 0 ? 2 : 1)) - u0;
        double dv = sorted.get(next, 0) - v0;
        double length = Math.hypot(du, dv);
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (int k = 0; k <= chain.size; k++) {
            int c = k < chain.size ? chain.at[k] : next;
            double v = sorted.get(c, 0) - v0;
            for (int end = 1; end <= 2; end++) {
                double offset = ((sorted.get(c, end) - u0) * dv - v * du) / length;
                lo = Math.min(lo, offset);
                hi = Math.max(hi, offset);
            }
        }
        return hi - lo <= BAND * side;
    }

    /** The widest band of steps joined, in sides. */
    static final double BAND = 2;

    /** @return the counter-clockwise hull, x, y, of the chain's squares (a rectangle for one run) */
    private double[] hull(Sorted sorted, Chain chain) {
        double h = side / 2;
        double[] uv = new double[8 * chain.size];
        int n = 0;
        for (int i = 0; i < chain.size; i++) {
            int c = chain.at[i];
            double v = sorted.get(c, 0);
            double from = sorted.get(c, 1);
            double to = sorted.get(c, 2);
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

    /** The runs in sorted order, read through the order rather than copied. */
    private record Sorted(Coordinates runs, int[] order) {
        double get(int k, int field) {
            return runs.get(order[k], field);
        }
    }

    /** The runs of one staircase, by sorted position. */
    private static final class Chain {
        int[] at = new int[16];
        int size;

        void clear() {
            size = 0;
        }

        void add(int k) {
            if (size == at.length) {
                at = Arrays.copyOf(at, 2 * size);
            }
            at[size++] = k;
        }
    }
}
