package robosim.geometry;

import java.util.List;

/**
 * The edges near one point, gathered once so that many range queries from around that point (a
 * ring of sonars, a laser scan) do not each search the whole world. Answers exactly as
 * {@link GeometryClient#rayRange} and {@link GeometryClient#coneRange} would for sensors within
 * the gathered radius.
 */
public final class Surroundings {
    private final Segment[] segments;

    Surroundings(List<Segment> segments) {
        this.segments = segments.toArray(new Segment[0]);
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
        for (Segment s : segments) {
            best = Math.min(best, s.rayHit(x, y, dx, dy));
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
        for (Segment s : segments) {
            if (s.farFrom(x, y, best)) {
                continue;
            }
            best = Math.min(best, s.wedgeDistance(x, y, rx, ry, lx, ly));
        }
        return best;
    }
}
