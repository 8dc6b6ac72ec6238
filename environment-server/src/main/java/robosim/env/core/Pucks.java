package robosim.env.core;

import java.util.ArrayList;
import java.util.List;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Polygon;
import robosim.env.camera.ColoredShape;
import robosim.env.world.WorldObject;
import robosim.geometry.BodyShape;
import robosim.geometry.GeometryClient;
import robosim.geometry.Pose2D;
import robosim.geometry.SweepResult;
import robosim.protocol.Colors;
import robosim.protocol.Snapshot;

/**
 * The world's movable objects (pucks): bodies in the geometry, so the robots' sonar and laser see
 * them, and the rule by which a robot driving into one pushes it.
 *
 * <p>The pushing rule, simple and deterministic: when a robot's sweep of one step is stopped by a
 * puck lying on the floor ahead of it in the direction it drives, the puck is swept along that
 * direction (the robot's heading, reversed when backing) by the rest of the robot's travel and
 * {@value #PUSH_MARGIN} mm more; then the robot's motion is swept again. A puck that meets a wall,
 * a robot or another puck stops there (pucks do not push pucks), and so the robot behind it stops
 * too, as at a wall. A robot turning on the spot into a puck does not push it: the puck stops the
 * turn as a wall would. Pushing is done in the robots' order, each against the others' latest
 * positions, as their motion is.
 *
 * <p>A puck held in a gripper is taken out of the geometry (not solid, not seen); the robot
 * carrying it has its body lengthened over it instead (see {@link Grippers}).
 */
final class Pucks implements Sweeper {
    /** The sides of the polygon a puck is simulated as: its corners stand at most 0.2 mm off its circle. */
    static final int SIDES = 32;
    /** How much further than the robot's remaining travel a pushed puck is swept, mm. */
    static final double PUSH_MARGIN = 1.0;
    /** A puck this near a robot's body touches it, mm. */
    static final double TOUCH = 1.0;

    private final GeometryFactory factory = new GeometryFactory();
    private final List<WorldObject> specs;
    private final int[] ids;
    private final double[] x;
    private final double[] y;
    /** Who holds each puck, or null when it lies on the floor. */
    private final String[] holder;

    /**
     * @param objects the world's objects at their start positions; they are not in any geometry
     *                until {@link #place}
     */
    Pucks(List<WorldObject> objects) {
        specs = List.copyOf(objects);
        int n = specs.size();
        ids = new int[n];
        x = new double[n];
        y = new double[n];
        holder = new String[n];
        for (int i = 0; i < n; i++) {
            x[i] = specs.get(i).x();
            y[i] = specs.get(i).y();
        }
    }

    /** Gives each object a body in the world's geometry, at its start position. */
    void place(GeometryClient geometry) {
        for (int i = 0; i < ids.length; i++) {
            ids[i] = geometry.addBody(BodyShape.disc(radius(i), SIDES), new Pose2D(x[i], y[i], 0));
        }
    }

    @Override
    public SweepResult sweep(GeometryClient geometry, int bodyId, double distance, double rotation) {
        SweepResult first = geometry.sweep(bodyId, distance, rotation);
        if (!first.blocked() || Math.abs(distance) < 1e-6 || ids.length == 0) {
            return first;
        }
        Pose2D at = first.pose();
        double dir = at.th() + (distance < 0 ? Math.PI : 0);
        double remaining = Math.abs(distance) * (1 - first.fraction());
        Polygon body = factory.createPolygon(geometry.bodyShape(bodyId).ringAt(at));
        boolean pushed = false;
        // the robot is behind the pucks it pushes: they are swept as if it were not there
        geometry.setSolid(bodyId, false);
        for (int i = 0; i < ids.length; i++) {
            if (holder[i] == null && touches(body, i) && ahead(at, dir, i)) {
                geometry.moveBody(ids[i], new Pose2D(x[i], y[i], dir));
                SweepResult p = geometry.sweep(ids[i], remaining + PUSH_MARGIN, 0);
                x[i] = p.pose().x();
                y[i] = p.pose().y();
                geometry.moveBody(ids[i], p.pose());
                pushed |= p.fraction() > 0;
            }
        }
        geometry.setSolid(bodyId, true);
        return pushed ? geometry.sweep(bodyId, distance, rotation) : first;
    }

    private boolean touches(Polygon body, int i) {
        return body.distance(factory.createPoint(new Coordinate(x[i], y[i]))) <= specs.get(i).radius() + TOUCH;
    }

    private boolean ahead(Pose2D at, double dir, int i) {
        return (x[i] - at.x()) * Math.cos(dir) + (y[i] - at.y()) * Math.sin(dir) > 0;
    }

    /** @return the number of objects */
    int count() {
        return ids.length;
    }

    double x(int i) {
        return x[i];
    }

    double y(int i) {
        return y[i];
    }

    double radius(int i) {
        return specs.get(i).radius();
    }

    /** @return who holds object {@code i}, or null */
    String holder(int i) {
        return holder[i];
    }

    /** @return the index of the object the robot holds, or -1 */
    int heldBy(String robot) {
        for (int i = 0; i < holder.length; i++) {
            if (robot.equals(holder[i])) {
                return i;
            }
        }
        return -1;
    }

    /** Takes object {@code i} off the floor into a robot's gripper: it is no longer solid. */
    void hold(GeometryClient geometry, int i, String robot) {
        holder[i] = robot;
        geometry.setSolid(ids[i], false);
    }

    /** Moves a held object along with its holder. */
    void carry(GeometryClient geometry, int i, double toX, double toY) {
        x[i] = toX;
        y[i] = toY;
        geometry.moveBody(ids[i], new Pose2D(toX, toY, 0));
    }

    /** Puts a held object down where it is: it is solid again. */
    void release(GeometryClient geometry, int i) {
        holder[i] = null;
        geometry.moveBody(ids[i], new Pose2D(x[i], y[i], 0));
        geometry.setSolid(ids[i], true);
    }

    /**
     * @param lifted whether each holder's lift is off the bottom, by holder name
     * @return each object where it is now, for viewers
     */
    /** How high a puck stands, as the camera sees it, mm: a hockey puck is an inch thick. */
    static final double CAMERA_HEIGHT = 25.4;

    /**
     * Adds each puck, as the camera sees it, to a scene: its outline (a polygon of {@value #SIDES}
     * sides) standing {@value #CAMERA_HEIGHT} mm from the floor, in the world file's colour. A held puck
     * is seen where it is carried, on the floor (the camera does not model the lift).
     *
     * @param shapes the scene
     */
    void addCameraShapes(List<ColoredShape> shapes) {
        for (int i = 0; i < ids.length; i++) {
            double r = radius(i);
            double[] xy = new double[2 * SIDES];
            for (int k = 0; k < SIDES; k++) {
                double a = 2 * Math.PI * k / SIDES;
                xy[2 * k] = x[i] + r * Math.cos(a);
                xy[2 * k + 1] = y[i] + r * Math.sin(a);
            }
            String color = specs.get(i).color();
            shapes.add(new ColoredShape(xy, CAMERA_HEIGHT, color == null ? ColoredShape.NO_COLOR : Colors.parse(color), -1));
        }
    }

    List<Snapshot.ObjectView> views(java.util.function.Predicate<String> lifted) {
        List<Snapshot.ObjectView> views = new ArrayList<>(ids.length);
        for (int i = 0; i < ids.length; i++) {
            views.add(new Snapshot.ObjectView(x[i], y[i], holder[i], holder[i] != null && lifted.test(holder[i])));
        }
        return views;
    }
}
