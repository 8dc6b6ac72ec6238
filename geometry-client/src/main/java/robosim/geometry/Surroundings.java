package robosim.geometry;

import java.util.List;

/**
 * The edges near one point, gathered once so that many range queries from around that point (a
 * ring of sonars, a laser scan) do not each search the whole world. Answers exactly as
 * {@link GeometryClient#rayRange} and {@link GeometryClient#coneRange} would for sensors within
 * the gathered radius.
 */
public final class Surroundings {
    private final double cx;
    private final double cy;
    private final Segment[] segments;
    /** Each segment's distance from the centre, ascending, in the order of {@link #segments}. */
    private final double[] nearest;

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
        for (int i = 0; i < n; i++) {
            segments[i] = found.get(order[i]);
            nearest[i] = d[order[i]];
        }
    }

    /** Runs shorter than this are sorted by insertion. */
    private static final int INSERTION_RUN = 16;

    /**
     * The indexes of {@code keys} in ascending order of their keys ({@link Double#compare}), equal
     * keys in the order they came: the order a stable sort gives, without boxing.
     */
    static int[] stableOrder(double[] keys) {
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
        for (int i = 0; i < segments.length; i++) {
            // no edge farther from the centre can be hit nearer than this
            if (nearest[i] - offset > best) {
                break;
            }
            best = Math.min(best, segments[i].rayHit(x, y, dx, dy));
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
        double rx = Math.cos(th - halfAngle);
        double ry = Math.sin(th - halfAngle);
        double lx = Math.cos(th + halfAngle);
        double ly = Math.sin(th + halfAngle);
        double best = maxRange;
        double offset = Math.sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy));
        for (int i = 0; i < segments.length; i++) {
            // no edge farther from the centre can be nearer the apex than this one
            if (nearest[i] - offset > best) {
                break;
            }
            best = Math.min(best, segments[i].wedgeDistance(x, y, rx, ry, lx, ly));
        }
        return best;
    }
}
