package robosim.env.world.xml;

import java.util.List;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Point;
import org.locationtech.jts.geom.Polygon;
import robosim.env.world.Obstacle;
import robosim.env.world.HeatSource;

/**
 * Turns {@code <heat>} elements into {@link HeatSource}s, checking that each lies inside the world
 * (its edge included) and not inside an obstacle. A source on an obstacle's edge is allowed, so
 * that something hot can stand against a wall.
 */
final class HeatPlacer {
    private final Attributes attributes;
    private final double width;
    private final double height;
    private final List<Polygon> obstacles;
    private final List<String> obstacleNames;
    private final GeometryFactory factory = new GeometryFactory();

    /**
     * @param obstacleNames how messages name each obstacle, in the order of {@code obstacles}
     */
    HeatPlacer(Attributes attributes, double width, double height, List<Obstacle> obstacles,
               List<String> obstacleNames) {
        this.attributes = attributes;
        this.width = width;
        this.height = height;
        this.obstacles = obstacles.stream().map(Obstacle::polygon).toList();
        this.obstacleNames = obstacleNames;
    }

    /** @return the heat source, checked */
    HeatSource place(HeatElement e) {
        double x = attributes.number(e, "x", e.x);
        double y = attributes.number(e, "y", e.y);
        double intensity = attributes.positive(e, "intensity", e.intensity);
        String where = (e.tag().equals("gold") ? "gold" : "heat source") + " at (" + Attributes.format(x) + ", " + Attributes.format(y) + ")";
        if (x < 0 || x > width || y < 0 || y > height) {
            throw attributes.error(e, where + " is outside the world " + Attributes.format(width) + " x "
                    + Attributes.format(height));
        }
        Point point = factory.createPoint(new Coordinate(x, y));
        for (int i = 0; i < obstacles.size(); i++) {
            if (obstacles.get(i).contains(point)) {
                throw attributes.error(e, where + " is inside " + obstacleNames.get(i));
            }
        }
        return new HeatSource(x, y, intensity, e.line());
    }
}
