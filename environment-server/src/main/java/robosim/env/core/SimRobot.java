package robosim.env.core;

import java.util.List;
import robosim.geometry.BodyShape;
import robosim.geometry.GeometryClient;
import robosim.geometry.Pose2D;
import robosim.geometry.Surroundings;
import robosim.geometry.SweepResult;
import robosim.protocol.Command;
import robosim.protocol.RobotState;
import robosim.protocol.params.RobotParameters;
import robosim.protocol.params.SonarUnit;

/**
 * One robot's simulated state: pose, velocities within its limits, stall, sonar, and the counts the
 * run reports. Owned and stepped by {@link Simulation}.
 */
final class SimRobot {
    /** MobileSim's sonar model: a 30° cone. */
    static final double SONAR_HALF_ANGLE = Math.toRadians(15);
    /** Nearer echoes are reported at this range, mm. */
    static final int SONAR_MIN_RANGE = 100;

    final String name;
    final String type;
    final RobotParameters params;
    final BodyShape body;
    final int bodyId;
    private final DriveController drive;
    private double x;
    private double y;
    private double th;
    private double vel;
    private double rotVel;
    private boolean stalled;
    private int collisions;
    private double distance;
    private final int[] sonar;
    boolean connected;

    SimRobot(String name, String type, RobotParameters params, BodyShape body, int bodyId,
             double x, double y, double th) {
        this.name = name;
        this.type = type;
        this.params = params;
        this.body = body;
        this.bodyId = bodyId;
        this.drive = new DriveController(params);
        this.x = x;
        this.y = y;
        this.th = Angles.fix(th);
        this.sonar = new int[params.sonarUnits().size()];
        java.util.Arrays.fill(sonar, (int) params.sonarMaxRange());
    }

    /** The body shape a robot's parameters describe. */
    static BodyShape bodyOf(RobotParameters p) {
        return BodyShape.rectangle(p.robotLengthFront(), p.robotLengthRear(), p.robotWidth());
    }

    void apply(List<Command> commands) {
        for (Command c : commands) {
            drive.apply(c, x, y, th);
        }
    }

    /** Advances the robot one step of {@code dt} seconds, stopping at contact. */
    void move(GeometryClient geometry, double dt) {
        if (drive.takeStop()) {
            vel = 0;
            rotVel = 0;
        }
        double wantV = drive.wantedVel(x, y, dt);
        double wantW = drive.wantedRotVel(th, dt, params.rotDecel());
        vel = approach(vel, wantV, params.transAccel(), params.transDecel(), dt);
        rotVel = approach(rotVel, wantW, params.rotAccel(), params.rotDecel(), dt);
        if (vel == 0 && rotVel == 0) {
            return;
        }
        SweepResult r = geometry.sweep(bodyId, vel * dt, Math.toRadians(rotVel) * dt);
        Pose2D p = r.pose();
        distance += Math.abs(vel * dt) * r.fraction();
        x = p.x();
        y = p.y();
        th = Angles.fix(Math.toDegrees(p.th()));
        geometry.moveBody(bodyId, pose());
        if (r.blocked()) {
            if (!stalled) {
                collisions++;
            }
            stalled = true;
            vel = 0;
            rotVel = 0;
        } else {
            stalled = false;
        }
    }

    /**
     * Moves {@code current} towards {@code target} by at most the acceleration (speeding up) or the
     * deceleration (slowing down) over {@code dt}.
     */
    static double approach(double current, double target, double accel, double decel, double dt) {
        boolean slowing = Math.abs(target) < Math.abs(current) || Math.signum(target) * Math.signum(current) < 0;
        double limit = (slowing ? decel : accel) * dt;
        double delta = Math.max(-limit, Math.min(limit, target - current));
        return current + delta;
    }

    void readSonar(GeometryClient geometry) {
        Pose2D p = pose();
        double max = params.sonarMaxRange();
        Surroundings near = geometry.around(x, y, max + body.radius(), bodyId);
        for (SonarUnit s : params.sonarUnits()) {
            double r = near.cone(p.worldX(s.x(), s.y()), p.worldY(s.x(), s.y()),
                    p.th() + Math.toRadians(s.th()), SONAR_HALF_ANGLE, max);
            sonar[s.index()] = (int) Math.round(Math.max(SONAR_MIN_RANGE, r));
        }
    }

    Pose2D pose() {
        return new Pose2D(x, y, Math.toRadians(th));
    }

    RobotState state(long step, long timeMs) {
        double diff = Math.toRadians(rotVel) / params.diffConvFactor() / 2;
        return new RobotState(step, timeMs, x, y, th, vel, rotVel, vel - diff, vel + diff,
                stalled, sonar.clone(), collisions);
    }

    double x() {
        return x;
    }

    double y() {
        return y;
    }

    double th() {
        return th;
    }

    boolean stalled() {
        return stalled;
    }

    int collisions() {
        return collisions;
    }

    double distance() {
        return distance;
    }

    int[] sonar() {
        return sonar.clone();
    }
}
