package robosim.env.sensors;

import java.util.List;
import java.util.function.Supplier;
import robosim.env.camera.ColoredShape;
import robosim.env.world.HeatSource;
import robosim.geometry.GeometryClient;
import robosim.geometry.Pose2D;
import robosim.geometry.Surroundings;

/**
 * What a robot's sensors read from, once every robot has moved. The walls and bodies around the
 * robot are gathered once, out to the farthest reach of its range sensors, for all of them.
 */
public final class SensorInput {
    private final GeometryClient geometry;
    private final Pose2D pose;
    private final double thDeg;
    private final int bodyId;
    private final double gatherRadius;
    private final List<HeatSource> heat;
    private final long timeMs;
    private final double dt;
    private final Supplier<List<ColoredShape>> scene;
    private Surroundings near;
    /** The robot's own surroundings, gathered into again each step; null to gather new ones. */
    private Surroundings reused;

    /**
     * @param geometry     the world
     * @param pose         the robot's true pose
     * @param thDeg        its true heading, degrees
     * @param bodyId       its body
     * @param gatherRadius how far from its centre to gather walls and bodies, mm; 0 for none
     * @param heat         the world's heat sources
     * @param timeMs       simulated time of the reading
     * @param dt           seconds since the previous reading (0 before the first step)
     * @param scene        what a camera sees, made when first asked for
     */
    public SensorInput(GeometryClient geometry, Pose2D pose, double thDeg, int bodyId, double gatherRadius,
                       List<HeatSource> heat, long timeMs, double dt, Supplier<List<ColoredShape>> scene) {
        this.geometry = geometry;
        this.pose = pose;
        this.thDeg = thDeg;
        this.bodyId = bodyId;
        this.gatherRadius = gatherRadius;
        this.heat = heat;
        this.timeMs = timeMs;
        this.dt = dt;
        this.scene = scene;
    }

    /** @return whether the robot's range sensors gather walls and bodies: whether any is on and reaches */
    boolean gathers() {
        return gatherRadius > 0;
    }

    /**
     * Has {@link #near} gather into the robot's own surroundings, which keep their arrays from one
     * step to the next, instead of into new ones.
     *
     * @param own the robot's surroundings, read by no other thread meanwhile
     */
    void gatherInto(Surroundings own) {
        reused = own;
    }

    /** @return the walls and bodies around the robot, out to its range sensors' reach */
    Surroundings near() {
        if (near == null) {
            near = reused == null ? geometry.around(pose.x(), pose.y(), gatherRadius, bodyId)
                    : geometry.gather(pose.x(), pose.y(), gatherRadius, bodyId, reused);
        }
        return near;
    }

    /** @return the world */
    GeometryClient geometry() {
        return geometry;
    }

    /** @return the robot's true pose */
    Pose2D pose() {
        return pose;
    }

    /** @return its true heading, degrees */
    double thDeg() {
        return thDeg;
    }

    /** @return its body */
    int bodyId() {
        return bodyId;
    }

    /** @return the world's heat sources */
    List<HeatSource> heat() {
        return heat;
    }

    /** @return simulated time of the reading, ms */
    long timeMs() {
        return timeMs;
    }

    /** @return seconds since the previous reading */
    double dt() {
        return dt;
    }

    /** @return the scenery, the pucks and every robot's body as a camera sees them */
    List<ColoredShape> scene() {
        return scene.get();
    }
}
