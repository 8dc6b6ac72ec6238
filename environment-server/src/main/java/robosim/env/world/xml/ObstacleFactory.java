package robosim.env.world.xml;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.operation.valid.IsValidOp;
import org.locationtech.jts.operation.valid.TopologyValidationError;
import robosim.geometry.GeometryClient;
import robosim.env.world.Obstacle;
import robosim.env.world.World;
import robosim.protocol.Colors;

/**
 * Turns {@code <wall>} and {@code <polygon>} elements into {@link Obstacle}s, checking their
 * geometry. A wall covers its segment widened by half its thickness on each side and extended by
 * half its thickness past each end (square caps), so that walls meeting at a point join without
 * a notch.
 */
final class ObstacleFactory {
    /** Thickness of a wall without a {@code thickness} attribute, and of boundary walls, mm. */
    static final double WALL_THICKNESS = 100;
    /** Height of an obstacle without a {@code height} attribute, and of boundary walls, mm. */
    static final double HEIGHT = 500;

    private final Attributes attributes;

    ObstacleFactory(Attributes attributes) {
        this.attributes = attributes;
    }

    Obstacle wall(WallElement e) {
        double x1 = attributes.coordinate(e, "x1", e.x1);
        double y1 = attributes.coordinate(e, "y1", e.y1);
        double x2 = attributes.coordinate(e, "x2", e.x2);
        double y2 = attributes.coordinate(e, "y2", e.y2);
        double thickness = attributes.atMost(e, "thickness",
                attributes.positive(e, "thickness", e.thickness, WALL_THICKNESS), World.MAX_SIZE);
        double height = attributes.positive(e, "height", e.height, HEIGHT);
        if (x1 == x2 && y1 == y2) {
            throw attributes.error(e, "wall from (" + Attributes.format(x1) + ", " + Attributes.format(y1)
                    + ") to (" + Attributes.format(x2) + ", " + Attributes.format(y2) + ") has zero length");
        }
        return new Obstacle(rectangle(x1, y1, x2, y2, thickness), height, e.line(), color(e, e.color));
    }

    /**
     * @return four walls of the default thickness lying just inside the edges of a world
     */
    static List<Obstacle> boundary(double width, double height, int line) {
        double h = WALL_THICKNESS / 2;
        List<Obstacle> walls = new ArrayList<>();
        walls.add(new Obstacle(rectangle(h, h, width - h, h, WALL_THICKNESS), HEIGHT, line));
        walls.add(new Obstacle(rectangle(width - h, h, width - h, height - h, WALL_THICKNESS), HEIGHT, line));
        walls.add(new Obstacle(rectangle(width - h, height - h, h, height - h, WALL_THICKNESS), HEIGHT, line));
        walls.add(new Obstacle(rectangle(h, height - h, h, h, WALL_THICKNESS), HEIGHT, line));
        return walls;
    }

    /** @return the obstacle moved by (dx, dy): boundary walls of a world that does not start at (0, 0) */
    static Obstacle moved(Obstacle o, double dx, double dy) {
        double[] xy = o.xy();
        for (int i = 0; i < xy.length; i += 2) {
            xy[i] += dx;
            xy[i + 1] += dy;
        }
        return new Obstacle(xy, o.height(), o.line(), o.color());
    }

    /** @return the {@code color} attribute as {@code #rrggbb}, or null when absent */
    private String color(Element e, String value) {
        if (value == null) {
            return null;
        }
        try {
            return Colors.format(Colors.parse(value));
        } catch (IllegalArgumentException bad) {
            throw attributes.error(e, "attribute color on <" + e.tag() + "> is " + Attributes.quote(value.trim())
                    + ", not a colour: give #rrggbb or one of "
                    + String.join(", ", new java.util.TreeSet<>(Colors.NAMES.keySet())));
        }
    }

    private static double[] rectangle(double x1, double y1, double x2, double y2, double thickness) {
        double length = Math.hypot(x2 - x1, y2 - y1);
        double h = thickness / 2;
        double ux = (x2 - x1) / length * h;
        double uy = (y2 - y1) / length * h;
        double ax = x1 - ux;
        double ay = y1 - uy;
        double bx = x2 + ux;
        double by = y2 + uy;
        // (uy, -ux) points to the right of the wall: right side first keeps the ring counter-clockwise
        return new double[] {ax + uy, ay - ux, bx + uy, by - ux, bx - uy, by + ux, ax - uy, ay + ux};
    }

    Obstacle polygon(PolygonElement e) {
        double[] xy = distinctRing(points(e, attributes.text(e, "points", e.points)));
        double height = attributes.positive(e, "height", e.height, HEIGHT);
        if (xy.length < 6) {
            throw attributes.error(e, "polygon has " + xy.length / 2 + " distinct point"
                    + (xy.length == 2 ? "" : "s") + " but needs at least 3");
        }
        if (collinear(xy)) {
            throw attributes.error(e, "polygon has zero area: all its points lie on one line");
        }
        TopologyValidationError invalid = new IsValidOp(GeometryClient.polygon(xy)).getValidationError();
        if (invalid != null) {
            Coordinate at = invalid.getCoordinate();
            String what = invalid.getMessage().toLowerCase(Locale.ROOT);
            throw attributes.error(e, "polygon is " + (what.contains("self-intersection") ? "self-intersecting"
                    : "invalid (" + what + ")") + " at (" + Attributes.format(at.x) + ", "
                    + Attributes.format(at.y) + ")");
        }
        return new Obstacle(signedArea(xy) < 0 ? reversed(xy) : xy, height, e.line(), color(e, e.color));
    }

    private double[] points(PolygonElement e, String text) {
        String[] words = text.split("[\\s,]+");
        if (words.length % 2 != 0) {
            throw attributes.error(e, "attribute points on <polygon> has " + words.length
                    + " numbers; it needs x,y pairs");
        }
        double[] xy = new double[words.length];
        for (int i = 0; i < words.length; i++) {
            xy[i] = attributes.coordinate(e, "points", words[i]);
        }
        return xy;
    }

    /** Drops repeated consecutive points, and the last point when it closes the ring. */
    private static double[] distinctRing(double[] xy) {
        List<double[]> kept = new ArrayList<>();
        for (int i = 0; i < xy.length; i += 2) {
            double[] p = {xy[i], xy[i + 1]};
            if (kept.isEmpty() || !same(kept.get(kept.size() - 1), p)) {
                kept.add(p);
            }
        }
        if (kept.size() > 1 && same(kept.get(0), kept.get(kept.size() - 1))) {
            kept.remove(kept.size() - 1);
        }
        double[] ring = new double[kept.size() * 2];
        for (int i = 0; i < kept.size(); i++) {
            ring[2 * i] = kept.get(i)[0];
            ring[2 * i + 1] = kept.get(i)[1];
        }
        return ring;
    }

    private static boolean same(double[] a, double[] b) {
        return a[0] == b[0] && a[1] == b[1];
    }

    private static boolean collinear(double[] xy) {
        for (int i = 4; i < xy.length; i += 2) {
            double cross = (xy[2] - xy[0]) * (xy[i + 1] - xy[1]) - (xy[3] - xy[1]) * (xy[i] - xy[0]);
            if (cross != 0) {
                return false;
            }
        }
        return true;
    }

    private static double signedArea(double[] xy) {
        double twice = 0;
        for (int i = 0; i < xy.length; i += 2) {
            int j = (i + 2) % xy.length;
            twice += xy[i] * xy[j + 1] - xy[j] * xy[i + 1];
        }
        return twice / 2;
    }

    private static double[] reversed(double[] xy) {
        double[] r = new double[xy.length];
        for (int i = 0; i < xy.length; i += 2) {
            r[xy.length - 2 - i] = xy[i];
            r[xy.length - 1 - i] = xy[i + 1];
        }
        return r;
    }
}

