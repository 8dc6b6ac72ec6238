package robosim.aria;

import java.io.IOException;
import java.util.List;
import robosim.hw.AbstractRobot;
import robosim.hw.HardwareOptions;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.Command;
import robosim.protocol.RobotState;
import robosim.protocol.params.RobotParameters;
import robosim.protocol.params.SonarUnit;

/**
 * The Pioneer Robot-Object, with ARIA's {@code ArRobot} semantics (see ARIA-SEMANTICS.md): units
 * mm, mm/s, degrees, deg/s; motion calls do not block; getters answer from the latest state the
 * Environment reported, which changes only while the robot's code is yielded (in
 * {@link ArUtil#sleep}), so a program reads a consistent snapshot.
 *
 * <pre>{@code
 * ArRobot robot = new ArRobot(name, host, port, "p3dx");
 * if (!robot.blockingConnect()) return;
 * robot.move(1000);
 * while (!robot.isMoveDone()) ArUtil.sleep(100);
 * robot.disconnect();
 * }</pre>
 */
public class ArRobot extends AbstractRobot {
    /** ARIA's default for {@link #isMoveDone(double)}, mm. */
    public static final double DEFAULT_MOVE_DONE = 40;
    /** ARIA's default for {@link #isHeadingDone(double)}, degrees. */
    public static final double DEFAULT_HEADING_DONE = 3;

    private final List<SonarUnit> sonarUnits;
    private volatile int[] sonar;
    private volatile ArPose moveStart;
    private volatile double moveDistance;
    private volatile Double headingTarget;
    private volatile double maxTransVel;
    private volatile double maxRotVel;

    /**
     * @param name      the robot's name in the world
     * @param host      the Environment's host
     * @param port      the Environment's robot port
     * @param paramFile the robot's parameter file: a path, or a shipped name such as {@code p3dx}
     */
    public ArRobot(String name, String host, int port, String paramFile) {
        this(name, host, port, RobotParameterFiles.load(paramFile));
    }

    /**
     * @param name       the robot's name in the world
     * @param host       the Environment's host
     * @param port       the Environment's robot port
     * @param parameters the robot's parameters
     */
    public ArRobot(String name, String host, int port, RobotParameters parameters) {
        super(name, host, port, "pioneer", parameters);
        this.sonarUnits = parameters.sonarUnits();
        this.maxTransVel = parameters.maxVelocity();
        this.maxRotVel = parameters.maxRVelocity();
        int[] unread = new int[sonarUnits.size()];
        java.util.Arrays.fill(unread, (int) parameters.sonarMaxRange());
        this.sonar = unread;
    }

    /**
     * Connects to the Environment, waiting (bounded) for its welcome.
     *
     * @return true if connected; otherwise {@link #getConnectionError()} says why
     */
    public boolean blockingConnect() {
        try {
            connect(HardwareOptions.defaults());
            return true;
        } catch (IOException | RuntimeException e) {
            setConnectionError(e.getMessage());
            return false;
        }
    }

    @Override
    protected void responded(RobotSensorResponse response) {
        sonar = response.state().sonar();
    }

    // ---- motion: none of these block ----

    /**
     * Travels a distance from the current pose; negative is backwards.
     *
     * @param distance mm
     */
    public void move(double distance) {
        moveStart = getPose();
        moveDistance = distance;
        request(new Command.Move(distance));
    }

    /** Translational and rotational velocity to zero at once. */
    public void stop() {
        moveStart = null;
        headingTarget = null;
        request(new Command.Stop());
    }

    /** @param velocity mm/s, rounded and clamped to the maximum translational velocity */
    public void setVel(double velocity) {
        moveStart = null;
        request(new Command.SetVel(Math.rint(velocity)));
    }

    /** @param velocity deg/s, counter-clockwise positive, clamped to the maximum rotational velocity */
    public void setRotVel(double velocity) {
        headingTarget = null;
        request(new Command.SetRotVel(velocity));
    }

    /**
     * Sets the wheel velocities; cancels any rotation command.
     *
     * @param leftVelocity  mm/s
     * @param rightVelocity mm/s
     */
    public void setVel2(double leftVelocity, double rightVelocity) {
        moveStart = null;
        headingTarget = null;
        request(new Command.SetVel2(leftVelocity, rightVelocity));
    }

    /** @param heading absolute heading to turn to, degrees */
    public void setHeading(double heading) {
        headingTarget = ArMath.fixAngle(heading);
        request(new Command.SetHeading(heading));
    }

    /** @param delta degrees to turn from the current heading */
    public void setDeltaHeading(double delta) {
        headingTarget = ArMath.fixAngle(getTh() + delta);
        request(new Command.SetDeltaHeading(delta));
    }

    /** @param velocity new translational limit, mm/s, within the parameter file's maximum */
    public void setMaxTransVel(double velocity) {
        maxTransVel = Math.max(0, Math.min(velocity, getParameters().maxVelocity()));
        request(new Command.SetMaxTransVel(velocity));
    }

    /** @param velocity new rotational limit, deg/s, within the parameter file's maximum */
    public void setMaxRotVel(double velocity) {
        maxRotVel = Math.max(0, Math.min(velocity, getParameters().maxRVelocity()));
        request(new Command.SetMaxRotVel(velocity));
    }

    /** @return the translational limit, mm/s */
    public double getMaxTransVel() {
        return maxTransVel;
    }

    /** @return the rotational limit, deg/s */
    public double getMaxRotVel() {
        return maxRotVel;
    }

    /** @return whether the last move is done, within {@value #DEFAULT_MOVE_DONE} mm */
    public boolean isMoveDone() {
        return isMoveDone(0);
    }

    /**
     * @param delta how close counts as done, mm; 0 means {@value #DEFAULT_MOVE_DONE}
     * @return true if no move is active, else whether the robot is at least |distance| − delta from
     *         where the move started
     */
    public boolean isMoveDone(double delta) {
        ArPose start = moveStart;
        if (start == null) {
            return true;
        }
        double d = delta <= 0 ? DEFAULT_MOVE_DONE : delta;
        return start.findDistanceTo(getPose()) >= Math.abs(moveDistance) - d;
    }

    /** @return whether the heading is reached, within {@value #DEFAULT_HEADING_DONE}° */
    public boolean isHeadingDone() {
        return isHeadingDone(0);
    }

    /**
     * @param delta how close counts as done, degrees; 0 means {@value #DEFAULT_HEADING_DONE}
     * @return true if no heading command is active, else whether |heading − target| ≤ delta
     */
    public boolean isHeadingDone(double delta) {
        Double target = headingTarget;
        if (target == null) {
            return true;
        }
        double d = delta <= 0 ? DEFAULT_HEADING_DONE : delta;
        return Math.abs(ArMath.subAngle(getTh(), target)) <= d;
    }

    // ---- state ----

    /** @return odometry x, mm */
    public double getX() {
        return state().x();
    }

    /** @return odometry y, mm */
    public double getY() {
        return state().y();
    }

    /** @return odometry heading, degrees in (-180, 180] */
    public double getTh() {
        return state().th();
    }

    /** @return the odometry pose, a new object */
    public ArPose getPose() {
        RobotState s = state();
        return new ArPose(s.x(), s.y(), s.th());
    }

    /** @return translational velocity, (left + right) / 2, mm/s */
    public double getVel() {
        return state().vel();
    }

    /** @return rotational velocity, deg/s */
    public double getRotVel() {
        return state().rotVel();
    }

    /** @return left wheel velocity, mm/s */
    public double getLeftVel() {
        return state().leftVel();
    }

    /** @return right wheel velocity, mm/s */
    public double getRightVel() {
        return state().rightVel();
    }

    /** @return whether a collision stopped the robot's last motion */
    public boolean isStalled() {
        return state().stalled();
    }

    /** @return whether either wheel is stalled; both are, when RoboSim stalls a robot */
    public boolean isLeftMotorStalled() {
        return isStalled();
    }

    /** @return whether either wheel is stalled; both are, when RoboSim stalls a robot */
    public boolean isRightMotorStalled() {
        return isStalled();
    }

    // ---- sonar ----

    /** @return the number of sonar units in the parameter file */
    public int getNumSonar() {
        return sonarUnits.size();
    }

    /**
     * @param num the sonar's index
     * @return its range from the transducer in mm; 5000 (the maximum) if it never reported; −1 for a
     *         bad index
     */
    public int getSonarRange(int num) {
        int[] s = sonar;
        return num < 0 || num >= s.length ? -1 : s[num];
    }

    /**
     * The nearest sonar range among the sonars mounted strictly inside an angle interval, by ARIA's
     * rule (see {@link ArMath#angleBetween}).
     *
     * @param startAngle degrees, robot-relative
     * @param endAngle   degrees, robot-relative
     * @return the range in mm, or −1 if no sonar is in the interval
     */
    public int getClosestSonarRange(double startAngle, double endAngle) {
        int n = getClosestSonarNumber(startAngle, endAngle);
        return n < 0 ? -1 : getSonarRange(n);
    }

    /**
     * @param startAngle degrees, robot-relative
     * @param endAngle   degrees, robot-relative
     * @return the index of the sonar with the nearest range inside the interval (ties to the lowest
     *         index), or −1 if none
     */
    public int getClosestSonarNumber(double startAngle, double endAngle) {
        int[] s = sonar;
        int best = -1;
        for (SonarUnit u : sonarUnits) {
            if (ArMath.angleBetween(u.th(), startAngle, endAngle) && (best < 0 || s[u.index()] < s[best])) {
                best = u.index();
            }
        }
        return best;
    }
}
