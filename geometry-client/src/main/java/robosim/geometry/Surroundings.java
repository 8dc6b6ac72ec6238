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
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            d[i] = found.get(i).distanceTo(cx, cy);
            order[i] = i;
        }
        java.util.Arrays.sort(order, (a, b) -> Double.compare(d[a], d[b]));
        segments = new Segment[n];
        nearest = new double[n];
        for (int i = 0; i < n; i++) {
            segments[i] = found.get(order[i]);
            nearest[i] = d[order[i]];
        }
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
