package robosim.viewer.view3d;

import java.awt.Color;
import java.util.ArrayList;
import java.util.List;
import robosim.geometry.Pose2D;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.Obstacle;
import robosim.protocol.WorldDescription.RobotInfo;
import robosim.protocol.RobotParameters;
import robosim.viewer.draw.BodyOutline;
import robosim.viewer.draw.Departures;
import robosim.viewer.draw.RobotPalette;
import robosim.viewer.draw.WorldRenderer;

/**
 * Builds the faces of the scene that the camera can see: each obstacle as a prism from the floor
 * to its height, in the colour the world gives it, each robot (but one gone from the run) as a prism of its body's footprint, with its heading marked on its
 * roof. Faces turned from the camera are left out. Long faces are cut into pieces of at most
 * {@value #PIECE_MM} mm, so that sorting them by their centres draws them in the right order.
 */
final class SceneBuilder {
    /** The longest piece a long face is cut into, mm. */
    static final double PIECE_MM = 400;
    /** The colour of walls and obstacles before shading. */
    static final Color WALL = new Color(176, 172, 164);
    private static final double[] UP = {0, 0, 1};
    private static final Color HEADING = new Color(25, 25, 25);
    private static final int CIRCLE_SIDES = 16;

    private SceneBuilder() {
    }

    static List<Face> build(WorldDescription world, Snapshot snapshot, Projection p) {
        List<Face> faces = new ArrayList<>();
        for (Obstacle o : world.obstacles()) {
            if (o.xy() != null && o.xy().length >= 6 && o.height() > 0 && Double.isFinite(o.height())) {
                prism(faces, p, ring(o.xy()), 0, o.height(), colour(o), null, null);
            }
        }
        if (snapshot != null) {
            List<RobotInfo> infos = world.robots();
            for (RobotView r : snapshot.robots()) {
                if (!Double.isFinite(r.x()) || !Double.isFinite(r.y()) || !Double.isFinite(r.th())
                        || Departures.gone(snapshot, r)) {
                    // a robot gone from the run is an outline on the floor (SolidRenderer), not a block
                    continue;
                }
                RobotInfo info = infos.stream().filter(i -> i.name().equals(r.name())).findFirst().orElse(null);
                Color colour = r.connected() ? WorldRenderer.colourOf(world, snapshot, r.name()) : RobotPalette.DISCONNECTED;
                Pose2D pose = new Pose2D(r.x(), r.y(), Math.toRadians(r.th()));
                double[] ring = footprint(pose, info == null ? null : info.parameters());
                double[] mark = heading(pose, info == null ? null : info.parameters());
                prism(faces, p, ring, 0, Projection.ROBOT_HEIGHT_MM, colour, mark,
                        r.stalled() ? RobotPalette.STALLED : HEADING);
            }
        }
        return faces;
    }

    /** @return an obstacle's colour before shading: the world's for it, or {@link #WALL} */
    static Color colour(Obstacle o) {
        return o.color() == null ? WALL : WorldRenderer.colourOf(o);
    }

    /**
     * @param r    a robot
     * @param info its parameters, or null
     * @return its body's footprint on the floor as x, y pairs, counter-clockwise
     */
    static double[] footprint(RobotView r, RobotInfo info) {
        return footprint(new Pose2D(r.x(), r.y(), Math.toRadians(r.th())), info == null ? null : info.parameters());
    }

    /** @return the ring as x, y pairs, counter-clockwise */
    private static double[] ring(double[] xy) {
        int n = xy.length / 2;
        double area = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            area += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
        }
        if (area >= 0) {
            return xy;
        }
        double[] ccw = new double[2 * n];
        for (int i = 0; i < n; i++) {
            ccw[2 * i] = xy[2 * (n - 1 - i)];
            ccw[2 * i + 1] = xy[2 * (n - 1 - i) + 1];
        }
        return ccw;
    }

    /** Adds the visible sides and the roof of a prism over a counter-clockwise ring. */
    private static void prism(List<Face> faces, Projection p, double[] ring, double bottom, double top,
                              Color colour, double[] mark, Color outline) {
        int n = ring.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ax = ring[2 * i];
            double ay = ring[2 * i + 1];
            double bx = ring[2 * j];
            double by = ring[2 * j + 1];
            double len = Math.hypot(bx - ax, by - ay);
            if (len < 1e-9) {
                continue;
            }
            double[] normal = {(by - ay) / len, -(bx - ax) / len, 0};
            if (!p.faces(normal)) {
                continue;
            }
            int pieces = (int) Math.ceil(len / PIECE_MM);
            for (int k = 0; k < pieces; k++) {
                double x0 = ax + (bx - ax) * k / pieces;
                double y0 = ay + (by - ay) * k / pieces;
                double x1 = ax + (bx - ax) * (k + 1) / pieces;
                double y1 = ay + (by - ay) * (k + 1) / pieces;
                faces.add(new Face(new double[] {x0, y0, bottom, x1, y1, bottom, x1, y1, top, x0, y0, top},
                        normal, colour, null, null));
            }
        }
        if (mark != null || n != 4) {
            faces.add(new Face(lift(ring, top), UP, colour, mark == null ? null : lift(mark, top), outline));
            return;
        }
        roofPieces(faces, ring, top, colour);
    }

    /** Cuts a four-cornered roof (a wall's) across its longer sides. */
    private static void roofPieces(List<Face> faces, double[] q, double top, Color colour) {
        boolean firstLonger = Math.hypot(q[2] - q[0], q[3] - q[1]) >= Math.hypot(q[4] - q[2], q[5] - q[3]);
        // corners a, b, c, d with a-b and d-c the long sides
        double[] a = firstLonger ? new double[] {q[0], q[1]} : new double[] {q[2], q[3]};
        double[] b = firstLonger ? new double[] {q[2], q[3]} : new double[] {q[4], q[5]};
        double[] c = firstLonger ? new double[] {q[4], q[5]} : new double[] {q[6], q[7]};
        double[] d = firstLonger ? new double[] {q[6], q[7]} : new double[] {q[0], q[1]};
        double len = Math.max(Math.hypot(b[0] - a[0], b[1] - a[1]), Math.hypot(c[0] - d[0], c[1] - d[1]));
        int pieces = Math.max(1, (int) Math.ceil(len / PIECE_MM));
        for (int k = 0; k < pieces; k++) {
            double s = (double) k / pieces;
            double t = (double) (k + 1) / pieces;
            faces.add(new Face(new double[] {
                lerp(a[0], b[0], s), lerp(a[1], b[1], s), top, lerp(a[0], b[0], t), lerp(a[1], b[1], t), top,
                lerp(d[0], c[0], t), lerp(d[1], c[1], t), top, lerp(d[0], c[0], s), lerp(d[1], c[1], s), top},
                    UP, colour, null, null));
        }
    }

    private static double lerp(double from, double to, double s) {
        return from + (to - from) * s;
    }

    private static double[] lift(double[] xy, double z) {
        double[] xyz = new double[xy.length / 2 * 3];
        for (int i = 0; i < xy.length / 2; i++) {
            xyz[3 * i] = xy[2 * i];
            xyz[3 * i + 1] = xy[2 * i + 1];
            xyz[3 * i + 2] = z;
        }
        return xyz;
    }

    /** The body as {@link BodyOutline} draws it: its rectangle, or a disc; counter-clockwise. */
    private static double[] footprint(Pose2D pose, RobotParameters p) {
        if (BodyOutline.isRectangle(p)) {
            double half = p.robotWidth() / 2;
            return place(pose, new double[] {p.robotLengthFront(), -half, p.robotLengthFront(), half,
                -p.robotLengthRear(), half, -p.robotLengthRear(), -half});
        }
        double r = BodyOutline.radius(p);
        double[] local = new double[2 * CIRCLE_SIDES];
        for (int i = 0; i < CIRCLE_SIDES; i++) {
            double a = 2 * Math.PI * i / CIRCLE_SIDES;
            local[2 * i] = r * Math.cos(a);
            local[2 * i + 1] = r * Math.sin(a);
        }
        return place(pose, local);
    }

    /** A triangle on the roof pointing the way the robot faces. */
    private static double[] heading(Pose2D pose, RobotParameters p) {
        double front = p != null && p.robotLengthFront() > 0 ? p.robotLengthFront() : 200;
        double half = p != null && p.robotWidth() > 0 ? p.robotWidth() / 4 : 80;
        return place(pose, new double[] {front * 0.9, 0, 0, half, 0, -half});
    }

    private static double[] place(Pose2D pose, double[] local) {
        double[] world = new double[local.length];
        for (int i = 0; i < local.length; i += 2) {
            world[i] = pose.worldX(local[i], local[i + 1]);
            world[i + 1] = pose.worldY(local[i], local[i + 1]);
        }
        return world;
    }
}
