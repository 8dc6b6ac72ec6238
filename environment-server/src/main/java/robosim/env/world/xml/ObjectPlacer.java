package robosim.env.world.xml;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Point;
import robosim.env.world.Bounds;
import robosim.env.world.Obstacle;
import robosim.env.world.RobotSpec;
import robosim.env.world.WorldObject;
import robosim.geometry.BodyShape;
import robosim.geometry.Pose2D;

/**
 * Turns {@code <object>} elements into {@link WorldObject}s, checking the type, the radius and
 * the colour, and that each object lies wholly inside the world, clear of the obstacles, of the
 * robots' start bodies and of the objects before it.
 */
final class ObjectPlacer {
    /** A colour is a name of letters (red, lightBlue) or {@code #rrggbb}. */
    private static final Pattern COLOR = Pattern.compile("[A-Za-z]{1,30}|#[0-9A-Fa-f]{6}");

    private final Attributes attributes;
    private final Bounds bounds;
    private final List<Obstacle> obstacles;
    private final List<String> obstacleNames;
    private final List<RobotSpec> robots;
    private final List<WorldObject> placed = new ArrayList<>();
    private final GeometryFactory factory = new GeometryFactory();

    /**
     * @param obstacleNames how messages name each obstacle, in the order of {@code obstacles}
     * @param robots        the robots at their start poses
     */
    ObjectPlacer(Attributes attributes, Bounds bounds, List<Obstacle> obstacles, List<String> obstacleNames,
                 List<RobotSpec> robots) {
        this.attributes = attributes;
        this.bounds = bounds;
        this.obstacles = obstacles;
        this.obstacleNames = obstacleNames;
        this.robots = robots;
    }

    /** @return the object, checked */
    WorldObject place(ObjectElement e) {
        String type = e.type == null ? WorldObject.PUCK : attributes.text(e, "type", e.type);
        if (!WorldObject.PUCK.equals(type)) {
            throw attributes.error(e, "type " + Attributes.quote(type) + " is not a type of object: the only one is '"
                    + WorldObject.PUCK + "'");
        }
        double x = attributes.number(e, "x", e.x);
        double y = attributes.number(e, "y", e.y);
        double radius = attributes.number(e, "radius", e.radius, WorldObject.DEFAULT_RADIUS);
        if (!(radius >= WorldObject.MIN_RADIUS && radius <= WorldObject.MAX_RADIUS)) {
            throw attributes.error(e, Attributes.format(radius) + " was supplied for radius: an object's radius is "
                    + Attributes.format(WorldObject.MIN_RADIUS) + " to " + Attributes.format(WorldObject.MAX_RADIUS)
                    + " mm");
        }
        if (e.color != null && !COLOR.matcher(e.color).matches()) {
            throw attributes.error(e, Attributes.quote(e.color)
                    + " was supplied for color: a colour is a name of letters "
                    + "(red) or #rrggbb");
        }
        String where = type + " at (" + Attributes.format(x) + ", " + Attributes.format(y) + ")";
        if (!bounds.contains(x - radius, y - radius) || !bounds.contains(x + radius, y + radius)) {
            throw attributes.error(e, where + " of radius " + Attributes.format(radius)
                    + " is not wholly inside the world " + bounds.describe());
        }
        Point centre = factory.createPoint(new Coordinate(x, y));
        for (int i = 0; i < obstacles.size(); i++) {
            if (obstacles.get(i).polygon().distance(centre) <= radius) {
                throw attributes.error(e, where + " touches " + obstacleNames.get(i));
            }
        }
        for (RobotSpec r : robots) {
            BodyShape body = RobotSpec.bodyOf(r.parameters());
            Pose2D pose = new Pose2D(r.x(), r.y(), Math.toRadians(r.th()));
            if (factory.createPolygon(body.ringAt(pose)).distance(centre) <= radius) {
                throw attributes.error(e, where + " touches robot " + r.name() + " at its start");
            }
        }
        for (WorldObject o : placed) {
            if (Math.hypot(o.x() - x, o.y() - y) <= o.radius() + radius) {
                throw attributes.error(e, where + " touches the object at line " + o.line());
            }
        }
        WorldObject object = new WorldObject(type, x, y, radius, e.color, e.line());
        placed.add(object);
        return object;
    }
}
