package robosim.geometry;

import java.util.Arrays;
import org.locationtech.jts.geom.Coordinate;

/**
 * A robot's body: a convex polygon in the robot's frame (x forward, y left, mm), counter-clockwise.
 */
public final class BodyShape {
    private final double[] xs;
    private final double[] ys;
    private final double radius;

    private BodyShape(double[] xs, double[] ys) {
        this.xs = xs;
        this.ys = ys;
        double r = 0;
        for (int i = 0; i < xs.length; i++) {
            r = Math.max(r, Math.hypot(xs[i], ys[i]));
        }
        this.radius = r;
    }

    /**
     * A rectangle about the centre of rotation.
     *
     * @param front mm ahead of the centre, greater than 0
     * @param rear  mm behind the centre, greater than 0
     * @param width mm across, greater than 0
     * @return the body
     */
    public static BodyShape rectangle(double front, double rear, double width) {
        positive("front", front);
        positive("rear", rear);
        positive("width", width);
        double h = width / 2;
        return new BodyShape(new double[] {front, -rear, -rear, front}, new double[] {h, h, -h, -h});
    }

    /**
     * A regular polygon approximating a circle about the centre of rotation.
     *
     * @param radius mm, greater than 0
     * @param sides  number of sides, at least 3
     * @return the body
     */
    public static BodyShape regularPolygon(double radius, int sides) {
        positive("radius", radius);
        if (sides < 3) {
            throw new IllegalArgumentException(sides + " was supplied for sides: sides must be at least 3");
        }
        double[] xs = new double[sides];
        double[] ys = new double[sides];
        for (int i = 0; i < sides; i++) {
            double a = 2 * Math.PI * i / sides;
            xs[i] = radius * Math.cos(a);
            ys[i] = radius * Math.sin(a);
        }
        return new BodyShape(xs, ys);
    }

    /**
     * A round body: a polygon of {@code sides} around a circle of {@code radius}, its faces
     * touching the circle, with faces (not corners) straight ahead, behind and to the sides, so the
     * body reaches exactly {@code radius} in those directions and at most {@code radius / cos(π/sides)}.
     *
     * @param radius mm, greater than 0
     * @param sides  a multiple of 4, at least 8
     * @return the body
     */
    public static BodyShape disc(double radius, int sides) {
        positive("radius", radius);
        if (sides < 8 || sides % 4 != 0) {
            throw new IllegalArgumentException(sides + " was supplied for sides: sides must be a multiple of 4, at least 8");
        }
        double corner = radius / Math.cos(Math.PI / sides);
        double[] xs = new double[sides];
        double[] ys = new double[sides];
        for (int i = 0; i < sides; i++) {
            double a = Math.PI / sides + 2 * Math.PI * i / sides;
            xs[i] = corner * Math.cos(a);
            ys[i] = corner * Math.sin(a);
        }
        return new BodyShape(xs, ys);
    }

    private static void positive(String name, double value) {
        if (!(value > 0) || !Double.isFinite(value)) {
            throw new IllegalArgumentException(value + " was supplied for " + name + ": " + name + " must be greater than 0");
        }
    }

    /** @return the distance from the centre of rotation to the farthest vertex */
    public double radius() {
        return radius;
    }

    /** @return the number of vertices */
    public int size() {
        return xs.length;
    }

    /**
     * @param pose where the body stands
     * @return the body's vertices in the world, counter-clockwise, ring closed (first repeated last)
     */
    public Coordinate[] ringAt(Pose2D pose) {
        // the heading's cosine and sine once for every vertex, not twice each: the vertices are
        // where Pose2D.worldX and worldY put them, bit for bit
        return ringAt(pose.x(), pose.y(), Math.cos(pose.th()), Math.sin(pose.th()));
    }

    /**
     * {@link #ringAt(Pose2D)} with the heading's cosine and sine already worked out, as a sweep has
     * them ({@link Arc}).
     *
     * @param x   mm
     * @param y   mm
     * @param cos the cosine of the heading
     * @param sin the sine of the heading
     * @return the body's vertices in the world, counter-clockwise, ring closed
     */
    Coordinate[] ringAt(double x, double y, double cos, double sin) {
        int n = xs.length;
        Coordinate[] ring = new Coordinate[n + 1];
        for (int i = 0; i < n; i++) {
            ring[i] = new Coordinate(x + xs[i] * cos - ys[i] * sin, y + xs[i] * sin + ys[i] * cos);
        }
        ring[n] = ring[0].copy();
        return ring;
    }

    @Override
    public String toString() {
        return "BodyShape" + Arrays.toString(xs) + Arrays.toString(ys);
    }
}
