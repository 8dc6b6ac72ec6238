package robosim.env.world;

import java.util.Arrays;
import org.locationtech.jts.geom.Polygon;
import robosim.geometry.GeometryClient;

/**
 * A static obstacle: a simple polygon with a height. A wall of the world file becomes the
 * rectangle it covers.
 *
 * @param xy     the outer ring x0, y0, x1, y1, ... in mm: at least three points, not closed
 *               (the first point is not repeated), counter-clockwise
 * @param height mm above the floor, greater than 0
 * @param line   the 1-based line of the element it came from in the world file
 * @param color  the colour the camera sees it in, {@code #rrggbb}; null when it has none
 */
public record Obstacle(double[] xy, double height, int line, String color) {

    /**
     * An obstacle without a colour.
     *
     * @param xy     the outer ring, mm
     * @param height mm
     * @param line   the world file's line
     */
    public Obstacle(double[] xy, double height, int line) {
        this(xy, height, line, null);
    }

    /** Copies the coordinates so the record stays immutable. */
    public Obstacle {
        xy = xy.clone();
    }

    /** @return a copy of the ring's coordinates */
    @Override
    public double[] xy() {
        return xy.clone();
    }

    /** @return the obstacle as a JTS polygon, as {@link GeometryClient} takes it */
    public Polygon polygon() {
        return GeometryClient.polygon(xy);
    }

    /** Compares the coordinates, not the array's identity. */
    @Override
    public boolean equals(Object o) {
        return o instanceof Obstacle other && Arrays.equals(xy, other.xy)
                && Double.compare(height, other.height) == 0 && line == other.line
                && java.util.Objects.equals(color, other.color);
    }

    @Override
    public int hashCode() {
        return 31 * (31 * (31 * Arrays.hashCode(xy) + Double.hashCode(height)) + line)
                + java.util.Objects.hashCode(color);
    }

    @Override
    public String toString() {
        return "Obstacle[xy=" + Arrays.toString(xy) + ", height=" + height + ", line=" + line
                + (color == null ? "" : ", color=" + color) + "]";
    }
}
