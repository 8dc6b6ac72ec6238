package robosim.env.core;

import java.util.Locale;
import org.locationtech.jts.geom.Coordinate;
import robosim.env.world.Bounds;
import robosim.geometry.BodyShape;
import robosim.geometry.GeometryClient;
import robosim.geometry.Pose2D;

/**
 * Puts robots at new true poses, as the simulator's own operations do (a robot's SIM_SET_POSE and
 * SIM_RESET, a control client's move): within the world file's coordinate bound, and only where
 * the body overlaps nothing.
 */
final class Placement {
    /** The farthest from the origin a robot may be placed, mm: the world file's coordinate bound. */
    static final double MAX = 1e8;

    private final GeometryClient geometry;

    Placement(GeometryClient geometry) {
        this.geometry = geometry;
    }

    /**
     * Places a robot, or says why not (then it stays where it is).
     *
     * @param r             the robot
     * @param to            where
     * @param resetOdometry whether its odometry starts again there (SIM_RESET) or stays (SIM_SET_POSE)
     * @param when          what the refusal says after the pose, for example {@code " at step 12"}
     * @return why the robot cannot be placed there, naming it and the pose; null once placed
     */
    String place(SimRobot r, Pose2D to, boolean resetOdometry, String when) {
        String refusal = refusal(r, to);
        if (refusal != null) {
            return "robot " + r.name + " cannot be placed at " + where(to) + when + ": " + refusal;
        }
        r.place(geometry, to, resetOdometry);
        return null;
    }

    private String refusal(SimRobot r, Pose2D to) {
        if (Math.abs(to.x()) > MAX || Math.abs(to.y()) > MAX) {
            return "a pose is within " + (long) MAX + " mm of the origin";
        }
        if (geometry.overlaps(r.body, to, r.bodyId)) {
            return "its body would overlap something there";
        }
        return null;
    }

    /** @return whether a body at a pose lies inside the world, its edge included */
    boolean inside(BodyShape body, Pose2D pose, Bounds bounds) {
        for (Coordinate c : body.ringAt(pose)) {
            if (!bounds.contains(c.x, c.y)) {
                return false;
            }
        }
        return true;
    }

    private static String where(Pose2D to) {
        return String.format(Locale.ROOT, "(%.0f, %.0f, %.0f)", to.x(), to.y(), Math.toDegrees(to.th()));
    }
}
