package robosim.geometry;

import java.util.List;

/**
 * The edges near one point, gathered once so that many range queries from around that point (a
 * ring of sonars, a laser scan) do not each search the whole world. Answers exactly as
 * {@link GeometryClient#rayRange} and {@link GeometryClient#coneRange} would for sensors within
 * the gathered radius.
 */
public final class Surroundings {
    /**
     * How far outside a cone or off a ray an edge must lie, beyond its own half length, to be
     * passed over without computing its range, mm: far above the rounding of either computation, so
     * an edge passed over is one whose range would have come out infinite.
     */
    private static final double SKIP_MARGIN = 1e-3;
    /** The rounding of coordinates grows with their size: this much per mm of coordinate. */
    private static final double SKIP_MARGIN_PER_MM = 1e-9;

    private final double cx;
    private final double cy;
    private final Segment[] segments;
    /** Each segment's distance from the centre, ascending, in the order of {@link #segments}. */
    private final double[] nearest;
    /** Each segment's first point and its vector to the second. */
    private final double[] x1;
    private final double[] y1;
    private final double[] ex;
    private final double[] ey;
    /** Each segment's midpoint, and its half length plus the margin for rounding. */
    private final double[] mx;
    private final double[] my;
    private final double[] slack;

    /** Sorts the edges by their distance from the centre, so a query can stop early. */
    Surroundings(double cx, double cy, List<Segment> found) {
        this.cx = cx;
        this.cy = cy;
        int n = found.size();
        double[] d = new double[n];
        for (int i = 0; i < n; i++) {
            d[i] = found.get(i).distanceTo(cx, cy);
        }
        int[] order = stableOrder(d);
        segments = new Segment[n];
        nearest = new double[n];
        x1 = new double[n];
        y1 = new double[n];
        ex = new double[n];
        ey = new double[n];
        mx = new double[n];
        my = new double[n];
        slack = new double[n];
        for (int i = 0; i < n; i++) {
            Segment e = found.get(order[i]);
            segments[i] = e;
            nearest[i] = d[order[i]];
            x1[i] = e.x1();
            y1[i] = e.y1();
            ex[i] = e.x2() - e.x1();
            ey[i] = e.y2() - e.y1();
            mx[i] = (e.x1() + e.x2()) / 2;
            my[i] = (e.y1() + e.y2()) / 2;
            slack[i] = Math.sqrt(ex[i] * ex[i] + ey[i] * ey[i]) / 2 + SKIP_MARGIN
                    + SKIP_MARGIN_PER_MM * (Math.abs(e.x1()) + Math.abs(e.y1()) + Math.abs(e.x2()) + Math.abs(e.y2()));
        }
    }

    /** A bucket holding more keys than this sends the keys to the merge sort. */
    private static final int MAX_BUCKET = 32;

    /**
     * The indexes of {@code keys} in ascending order of their keys ({@link Double#compare}), equal
     * keys in the order they came: the order a stable sort gives, without boxing. The keys (the
     * edges' distances) are spread evenly enough for a bucket sort: a counting sort into as many
     * buckets as keys, each bucket a slice of the range up to the largest key, then insertion by
     * the exact key and index, which has only the few keys sharing a bucket to put in order.
     */
    static int[] stableOrder(double[] keys) {
        int n = keys.length;
        double max = 0;
        for (double k : keys) {
            if (k > max) {
                max = k;
            }
        }
        if (n < 2 || !(max > 0 && max < Double.POSITIVE_INFINITY)) {
            return mergeOrder(keys);
        }
        double scale = (n - 1) / max;
        int[] start = new int[n + 1];
        int[] bucket = new int[n];
        for (int i = 0; i < n; i++) {
            double b = keys[i] * scale;
            int k = b >= 0 ? (int) Math.min(n - 1, b) : 0;
            bucket[i] = k;
            if (++start[k + 1] > MAX_BUCKET) {
                return mergeOrder(keys);
            }
        }
        for (int k = 0; k < n; k++) {
            start[k + 1] += start[k];
        }
        int[] order = new int[n];
        for (int i = 0; i < n; i++) {
            order[start[bucket[i]]++] = i;
        }
        for (int p = 1; p < n; p++) {
            int v = order[p];
            int j = p - 1;
            while (j >= 0 && after(keys, order[j], v)) {
                order[j + 1] = order[j];
                j--;
            }
            order[j + 1] = v;
        }
        return order;
    }

    /** @return whether index {@code a} comes after index {@code b}: a larger key, or an equal key and a larger index */
    private static boolean after(double[] keys, int a, int b) {
        int c = Double.compare(keys[a], keys[b]);
        return c > 0 || c == 0 && a > b;
    }

    /** Runs shorter than this are sorted by insertion. */
    private static final int INSERTION_RUN = 16;

    /** {@link #stableOrder} by a merge sort, for any keys. */
    static int[] mergeOrder(double[] keys) {
        int n = keys.length;
        int[] a = new int[n];
        for (int i = 0; i < n; i++) {
            a[i] = i;
        }
        for (int lo = 0; lo < n; lo += INSERTION_RUN) {
            int hi = Math.min(n, lo + INSERTION_RUN);
            for (int i = lo + 1; i < hi; i++) {
                int v = a[i];
                int j = i - 1;
                while (j >= lo && Double.compare(keys[a[j]], keys[v]) > 0) {
                    a[j + 1] = a[j];
                    j--;
                }
                a[j + 1] = v;
            }
        }
        int[] b = new int[n];
        for (int width = INSERTION_RUN; width < n; width *= 2) {
            for (int lo = 0; lo < n; lo += 2 * width) {
                int mid = Math.min(n, lo + width);
                int hi = Math.min(n, lo + 2 * width);
                int i = lo;
                int j = mid;
                int k = lo;
                while (i < mid && j < hi) {
                    // the left run wins ties: equal keys keep their order
                    b[k++] = Double.compare(keys[a[j]], keys[a[i]]) < 0 ? a[j++] : a[i++];
                }
                while (i < mid) {
                    b[k++] = a[i++];
                }
                while (j < hi) {
                    b[k++] = a[j++];
                }
            }
            int[] t = a;
            a = b;
            b = t;
        }
        return a;
    }

    /** @return the edges gathered, nearest the centre first (equal distances in the order found) */
    List<Segment> edges() {
        return List.of(segments);
    }

    /** @return the number of edges gathered */
    public int size() {
        return segments.length;
    }

    /**
     * The distance along a ray to the first edge it meets.
     *
     * @param x        ray origin x, mm
     * @param y        ray origin y, mm
     * @param th       direction, radians
     * @param maxRange farthest distance looked at, mm
     * @return the distance, or {@code maxRange} if nothing is nearer
     */
    public double ray(double x, double y, double th, double maxRange) {
        double dx = Math.cos(th);
        double dy = Math.sin(th);
        double best = maxRange;
        double offset = Math.sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy));
        double apexSlack = SKIP_MARGIN_PER_MM * (Math.abs(x) + Math.abs(y));
        for (int i = 0; i < segments.length; i++) {
            // no edge farther from the centre can be hit nearer than this
            if (nearest[i] - offset > best) {
                break;
            }
            // an edge wholly to one side of the ray's line, or behind its origin, is missed
            double ax = mx[i] - x;
            double ay = my[i] - y;
            double off = slack[i] + apexSlack;
            double side = dx * ay - dy * ax;
            if (side > off || side < -off || dx * ax + dy * ay < -off) {
                continue;
            }
            best = Math.min(best, Segment.rayHit(x1[i], y1[i], ex[i], ey[i], x, y, dx, dy));
        }
        return best;
    }

    /**
     * The distance to the nearest edge inside a cone (see {@link GeometryClient#coneRange}).
     *
     * @param x         apex x, mm
     * @param y         apex y, mm
     * @param th        cone axis, radians
     * @param halfAngle half the cone's opening, radians, below π/2
     * @param maxRange  farthest distance looked at, mm
     * @return the distance, or {@code maxRange} if nothing is nearer
     */
    public double cone(double x, double y, double th, double halfAngle, double maxRange) {
        return wedge(x, y, Math.cos(th - halfAngle), Math.sin(th - halfAngle),
                Math.cos(th + halfAngle), Math.sin(th + halfAngle), maxRange);
    }

    /**
     * {@link #cone} with the cone's edges given as unit vectors, so that a sensor whose cones keep
     * their directions from one reading to the next (a robot that has not turned) need not work
     * out their sines and cosines again.
     *
     * @param x        apex x, mm
     * @param y        apex y, mm
     * @param rx       x of the unit vector along the cone's right edge: {@code cos(th - halfAngle)}
     * @param ry       its y: {@code sin(th - halfAngle)}
     * @param lx       x of the unit vector along its left edge: {@code cos(th + halfAngle)}
     * @param ly       its y: {@code sin(th + halfAngle)}
     * @param maxRange farthest distance looked at, mm
     * @return the distance, or {@code maxRange} if nothing is nearer
     */
    public double wedge(double x, double y, double rx, double ry, double lx, double ly, double maxRange) {
        double best = maxRange;
        double offset = Math.sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy));
        double apexSlack = SKIP_MARGIN_PER_MM * (Math.abs(x) + Math.abs(y));
        for (int i = 0; i < segments.length; i++) {
            // no edge farther from the centre can be nearer the apex than this one
            if (nearest[i] - offset > best) {
                break;
            }
            // an edge wholly outside either side of the wedge has no part inside it
            double ax = mx[i] - x;
            double ay = my[i] - y;
            double off = -(slack[i] + apexSlack);
            if (rx * ay - ry * ax < off || ax * ly - ay * lx < off) {
                continue;
            }
            best = Math.min(best, Segment.wedgeDistance(x1[i], y1[i], ex[i], ey[i], x, y, rx, ry, lx, ly));
        }
        return best;
    }
}
