package robosim.aria;

import robosim.protocol.RobotState;

/**
 * The bump rings as a range device (ARIA's {@code ArBumpers}), named {@code bumpers}: each cycle,
 * for each pressed bumper of a ring the robot has ({@link ArRobot#hasFrontBumpers()},
 * {@link ArRobot#hasRearBumpers()}), it adds a current reading on the circle of the robot's radius
 * at the bumper's place, {@code 67.5 − (i + 0.5)·angleRange/n} degrees for front bumper i of n and
 * 180° more for a rear one, as ARIA's {@code ArBumpers.cpp} does. Which bumpers are pressed comes from
 * {@link ArRobot#getStallValue()}. Readings stay in the current buffer for
 * {@value #DEFAULT_MAX_SECONDS_TO_KEEP_CURRENT} s; the cumulative buffer is not used.
 *
 * <pre>{@code
 * ArBumpers bumpers = new ArBumpers();
 * robot.addRangeDevice(bumpers);
 * if (bumpers.currentReadingPolar(-90, 90) < robot.getRobotRadius() + 1) robot.stop();
 * }</pre>
 */
public class ArBumpers extends ArRangeDevice {
    /** ARIA's {@code ArBumpers} default for how long a bump is kept, s. */
    public static final int DEFAULT_MAX_SECONDS_TO_KEEP_CURRENT = 15;
    /** ARIA's {@code ArBumpers} default buffer sizes. */
    public static final int DEFAULT_BUFFER_SIZE = 30;
    /** The range ARIA's {@code ArBumpers} gives itself, mm. */
    public static final double DEFAULT_MAX_RANGE = 5000;

    private final double angleRange;

    /** Bumpers with ARIA's defaults: buffers of 30, bumps kept 15 s, the rings spanning 135°. */
    public ArBumpers() {
        this(DEFAULT_BUFFER_SIZE, DEFAULT_BUFFER_SIZE, "bumpers", DEFAULT_MAX_SECONDS_TO_KEEP_CURRENT,
                StallValue.ANGLE_RANGE);
    }

    /**
     * @param currentBufferSize       how many bumps the current buffer keeps
     * @param cumulativeBufferSize    the cumulative buffer's size (unused, as in ARIA)
     * @param name                    the device's name
     * @param maxSecondsToKeepCurrent how long a bump is kept, s
     * @param angleRange              the degrees each ring spans, shared evenly by its bumpers
     * @throws IllegalArgumentException if the angle range is not above 0 and at most 360
     */
    public ArBumpers(int currentBufferSize, int cumulativeBufferSize, String name, int maxSecondsToKeepCurrent,
                     double angleRange) {
        super(name, DEFAULT_MAX_RANGE, currentBufferSize, cumulativeBufferSize);
        if (!(angleRange > 0 && angleRange <= 360)) {
            throw new IllegalArgumentException(angleRange
                    + " was supplied for angleRange: a ring spans more than 0 and at most 360 degrees");
        }
        this.angleRange = angleRange;
        setMaxSecondsToKeepCurrent(maxSecondsToKeepCurrent);
        setMaxSecondsToKeepCumulative(0);
        setMaxDistToKeepCumulative(0);
    }

    /** @return the degrees each ring spans */
    public double getAngleRange() {
        return angleRange;
    }

    /** Adds a reading at each pressed bumper. */
    @Override
    protected void processReadings() {
        ArRobot robot = getRobot();
        RobotState s = cycleState();
        if (robot == null || s == null) {
            return;
        }
        int stall = robot.getStallValue();
        if (robot.hasFrontBumpers()) {
            addBumps(robot, (stall >> 9) & 0x7f, robot.getNumFrontBumpers(), 0, s.timeMs());
        }
        if (robot.hasRearBumpers()) {
            addBumps(robot, (stall >> 1) & 0x7f, robot.getNumRearBumpers(), 180, s.timeMs());
        }
    }

    private void addBumps(ArRobot robot, int flags, int n, double turn, long timeMs) {
        ArPose pose = robotPose();
        ArTransform toGlobal = new ArTransform(new ArPose(), pose);
        double radius = robot.getRobotRadius();
        for (int i = 0; i < n; i++) {
            if ((flags & 1 << i) != 0) {
                double th = Math.toRadians(StallValue.bumperAngle(i, n, angleRange) + turn);
                double lx = radius * Math.cos(th);
                double ly = radius * Math.sin(th);
                addCurrentReading(toGlobal.transformX(lx, ly), toGlobal.transformY(lx, ly), pose, timeMs);
            }
        }
    }
}
