package robosim.env.core;

import java.util.List;
import java.util.function.Supplier;
import java.util.random.RandomGenerator;
import org.locationtech.jts.geom.Envelope;
import robosim.env.camera.ColoredShape;
import robosim.env.sensors.RobotSensors;
import robosim.env.sensors.Sensor;
import robosim.env.sensors.SensorInput;
import robosim.env.sensors.SensorSetup;
import robosim.env.world.HeatSource;
import robosim.env.world.Noise;
import robosim.geometry.Angles;
import robosim.geometry.BodyShape;
import robosim.geometry.GeometryClient;
import robosim.geometry.Pose2D;
import robosim.geometry.SweepResult;
import robosim.protocol.Command;
import robosim.protocol.GripperState;
import robosim.protocol.MessageDelivery;
import robosim.protocol.RobotKind;
import robosim.protocol.RobotState;
import robosim.protocol.RobotParameters;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/**
 * One robot's simulated state: its true pose and its odometry, velocities within its limits, stall,
 * sensors, and the counts the run reports. Owned and stepped by {@link Simulation}.
 */
final class SimRobot {
    final String name;
    final String type;
    final RobotParameters params;
    final BodyShape body;
    final int bodyId;
    /** The robot's own noise stream, shared by its sensors and its odometry. */
    final RandomGenerator random;
    private final DriveController drive;
    private double x;
    private double y;
    private double th;
    private double vel;
    private double rotVel;
    private boolean stalled;
    private int collisions;
    /** How many times the stall flag went up. */
    private int stalls;
    private double distance;
    private final RobotSensors sensors;
    private final Odometry odometry;
    boolean connected;
    /** How its motion is swept: through the world's pucks, which it pushes. */
    Sweeper sweeper = Sweeper.PLAIN;
    private final Motors motors;

    SimRobot(String name, String type, RobotParameters params, BodyShape body, int bodyId,
             double x, double y, double th, Noise noise, RandomGenerator random, boolean motorsEnabled) {
        this.name = name;
        this.type = type;
        this.params = params;
        this.body = body;
        this.bodyId = bodyId;
        this.random = random;
        this.drive = new DriveController(params);
        this.x = x;
        this.y = y;
        this.th = Angles.fix(th);
        this.sensors = new RobotSensors(new SensorSetup(params, noise, random));
        this.odometry = new Odometry(x, y, this.th, noise.odometryError(), random);
        this.motors = new Motors(RobotKind.of(type).map(RobotKind::hasMotorSwitch).orElse(true), motorsEnabled);
    }

    /** Hands a motion command to the drive controller, which steers by odometry. */
    void drive(Command.Motion command) {
        drive.apply(command, odometry.x(), odometry.y(), odometry.th());
    }

    /**
     * Carries out a motion command of the robot's program: a motor switch, or a command for the
     * drive controller unless the motors are disabled.
     *
     * @param command the command
     * @return null when carried out; otherwise why not, to tell the robot ("" when it was told already)
     */
    String command(Command.Motion command) {
        if (command instanceof Command.SetMotors m) {
            if (motors.set(m.on())) {
                drive(new Command.Stop()); // as ENABLE 0 stops a Pioneer
            }
            return null;
        }
        String refusal = motors.refusal(command);
        if (refusal == null) {
            drive(command);
        }
        return refusal;
    }

    /**
     * A program has connected: the motors are as the world says a program finds them.
     *
     * @param enabled whether they are enabled
     */
    void motorsAtConnect(boolean enabled) {
        if (motors.set(enabled)) {
            drive(new Command.Stop());
        }
    }

    /** Advances the robot one step of {@code dt} seconds, stopping at contact. */
    void move(GeometryClient geometry, double dt) {
        if (drive.takeStop()) {
            vel = 0;
            rotVel = 0;
        }
        // the controller steers by odometry, as a robot's firmware does
        double wantV = drive.wantedVel(odometry.x(), odometry.y(), dt, vel);
        double wantW = drive.wantedRotVel(odometry.th(), dt, rotVel);
        // the way covered is the integral of each speed's ramp this step, not the end speed times dt
        SpeedProfile trans = SpeedProfile.step(vel, wantV, drive.transAccel(), drive.transDecel(), dt);
        SpeedProfile rot = SpeedProfile.step(rotVel, wantW, drive.rotAccel(), drive.rotDecel(), dt);
        vel = trans.speed();
        rotVel = rot.speed();
        if (trans.distance() == 0 && rot.distance() == 0) {
            sensors.moved(new Sensor.Moved(geometry, bodyId, th, 0, 0, dt));
            return;
        }
        double turn = Math.toRadians(rot.distance());
        SweepResult r = sweeper.sweep(geometry, bodyId, trans.distance(), turn);
        double covered = trans.distance() * r.fraction();
        double turned = turn * r.fraction();
        Pose2D p = r.pose();
        distance += Math.abs(covered);
        x = p.x();
        y = p.y();
        th = Angles.fix(Math.toDegrees(p.th()));
        geometry.moveBody(bodyId, pose());
        odometry.travel(covered, turned, x, y, th);
        double half = turned / params.diffConvFactor();
        drive.travelled(covered - half, covered + half);
        sensors.moved(new Sensor.Moved(geometry, bodyId, th, covered - half, covered + half, dt));
        if (r.blocked()) {
            // a collision is counted as the robot becomes stalled, not at each step it stays so
            if (!stalled) {
                collisions++;
                stalls++;
            }
            stalled = true;
            vel = 0;
            rotVel = 0;
        } else {
            stalled = false;
        }
    }

    /**
     * Reads the robot's sensors where it truly is.
     *
     * @param geometry the world
     * @param heat     its heat sources
     * @param timeMs   simulated time of the reading
     * @param dt       seconds since the previous reading (0 before the first step)
     * @param scene    what a camera sees, made when first asked for
     */
    void readSensors(GeometryClient geometry, List<HeatSource> heat, long timeMs, double dt,
                     Supplier<List<ColoredShape>> scene) {
        sensors.sense(new SensorInput(geometry, pose(), th, bodyId, sensors.gatherRadius(body.radius()), heat, timeMs,
                dt, scene));
    }

    /**
     * @param env an envelope in the world
     * @return whether a body within it could change what this robot's range sensors read now
     */
    boolean sees(Envelope env) {
        double r = sensors.gatherRadius(body.radius());
        if (r <= 0) {
            return false;
        }
        return env.intersects(new Envelope(x - r, x + r, y - r, y + r));
    }

    /**
     * Puts the robot at a new true pose, where the caller has checked that it fits.
     *
     * @param geometry      where its body is
     * @param pose          the new pose
     * @param resetOdometry whether the odometry starts again at the new pose (SIM_RESET) or stays (SIM_SET_POSE)
     */
    void place(GeometryClient geometry, Pose2D pose, boolean resetOdometry) {
        x = pose.x();
        y = pose.y();
        th = Angles.fix(Math.toDegrees(pose.th()));
        geometry.moveBody(bodyId, pose);
        stalled = false;
        if (resetOdometry) {
            vel = 0;
            rotVel = 0;
            drive(new Command.Stop());
            odometry.reset(x, y, th);
        } else {
            odometry.placed(x, y, th);
        }
        sensors.moved(new Sensor.Moved(geometry, bodyId, th, 0, 0, 0));
    }

    Pose2D pose() {
        return new Pose2D(x, y, Math.toRadians(th));
    }

    RobotState state(long step, long timeMs, List<MessageDelivery> messages, List<String> errors,
                     GripperState gripper) {
        double diff = Math.toRadians(rotVel) / params.diffConvFactor();
        StateParts parts = sensors.report(StateParts.NONE, new TruePose(x, y, th)).with(GripperState.PART, gripper);
        return new RobotState(step, timeMs, odometry.x(), odometry.y(), odometry.th(), vel, rotVel,
                vel - diff, vel + diff, stalled, collisions, messages, errors, motors.enabled(), parts);
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

    double vel() {
        return vel;
    }

    double rotVel() {
        return rotVel;
    }

    boolean stalled() {
        return stalled;
    }

    int collisions() {
        return collisions;
    }

    int stalls() {
        return stalls;
    }

    double distance() {
        return distance;
    }

    RobotSensors sensors() {
        return sensors;
    }

    Odometry odometry() {
        return odometry;
    }
}
