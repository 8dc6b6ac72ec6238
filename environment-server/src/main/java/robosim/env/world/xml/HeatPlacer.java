package robosim.env.world.xml;

import java.util.List;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Point;
import robosim.env.world.Bounds;
import robosim.env.world.HeatSource;
import robosim.env.world.Obstacle;

/**
 * Turns {@code <heat>} elements into {@link HeatSource}s, checking that each lies inside the world
 * (its edge included) and not inside an obstacle. A source on an obstacle's edge is allowed, so
 * that something hot can stand against a wall.
 */
final class HeatPlacer {
    private final Attributes attributes;
    private final Bounds bounds;
    private final List<Obstacle> obstacles;
    private final List<String> obstacleNames;
    private final GeometryFactory factory = new GeometryFactory();

    /**
     * @param obstacleNames how messages name each obstacle, in the order of {@code obstacles}
     */
    HeatPlacer(Attributes attributes, Bounds bounds, List<Obstacle> obstacles, List<String> obstacleNames) {
        this.attributes = attributes;
        this.bounds = bounds;
        this.obstacles = obstacles;
        this.obstacleNames = obstacleNames;
    }

    /** @return the heat source, checked */
    HeatSource place(HeatElement e) {
        double x = attributes.number(e, "x", e.x);
        double y = attributes.number(e, "y", e.y);
        double intensity = attributes.positive(e, "intensity", e.intensity);
        String where = (e.tag().equals("gold") ? "gold" : "heat source") + " at (" + Attributes.format(x) + ", " + Attributes.format(y) + ")";
        if (!bounds.contains(x, y)) {
            throw attributes.error(e, where + " is outside the world " + bounds.describe());
        }
        Point point = factory.createPoint(new Coordinate(x, y));
        for (int i = 0; i < obstacles.size(); i++) {
            // the box test first: a map's world has a polygon for each of 10^5 points
            if (inBox(obstacles.get(i).xy(), x, y) && obstacles.get(i).polygon().contains(point)) {
                throw attributes.error(e, where + " is inside " + obstacleNames.get(i));
            }
        }
        return new HeatSource(x, y, intensity, e.line());
    }

    private static boolean inBox(double[] xy, double x, double y) {
        double minX = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < xy.length; i += 2) {
            minX = Math.min(minX, xy[i]);
            maxX = Math.max(maxX, xy[i]);
            minY = Math.min(minY, xy[i + 1]);
            maxY = Math.max(maxY, xy[i + 1]);
        }
        return x >= minX && x <= maxX && y >= minY && y <= maxY;
    }
}
