package robosim.aria;

import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import robosim.protocol.RobotState;

/**
 * A range device attached to a robot (ARIA's {@code ArRangeDevice}): the sonar ring, a laser.
 * Add one with {@link ArRobot#addRangeDevice}.
 *
 * <p>A device keeps two buffers of readings, in global mm, newest first: the current buffer (what
 * the device sees now) and the cumulative buffer (what it has seen lately, a local map). Adding to
 * a full buffer evicts the oldest reading. Each robot cycle, in a sensor-interpretation task, the
 * device takes its new readings ({@link #processReadings()}) and prunes, by ARIA's rules: current
 * readings older than {@value #DEFAULT_MAX_SECONDS_TO_KEEP_CURRENT} s go; cumulative readings
 * older than {@value #DEFAULT_MAX_SECONDS_TO_KEEP_CUMULATIVE} s or farther than
 * {@value #DEFAULT_MAX_DIST_TO_KEEP_CUMULATIVE} mm from the robot go; and a new cumulative reading
 * closer than {@value #DEFAULT_MIN_DIST_BETWEEN_CUMULATIVE} mm to older ones replaces them. The
 * buffers are pruned again whenever they are read.
 *
 * <p>Times are the simulated time of the state the robot's cycle delivered; positions are the
 * robot's odometry pose in that state. A device with no robot, or before the first state, prunes
 * nothing by age or distance and answers queries from the origin, heading 0.
 */
public class ArRangeDevice {
    /** The current buffer's size when none is given: ARIA's sonar default. */
    public static final int DEFAULT_CURRENT_BUFFER_SIZE = 24;
    /** The cumulative buffer's size when none is given: ARIA's sonar default. */
    public static final int DEFAULT_CUMULATIVE_BUFFER_SIZE = 64;
    /** How long a current reading is kept, s. */
    public static final int DEFAULT_MAX_SECONDS_TO_KEEP_CURRENT = 5;
    /** How long a cumulative reading is kept, s. */
    public static final int DEFAULT_MAX_SECONDS_TO_KEEP_CUMULATIVE = 15;
    /** How far from the robot a cumulative reading is kept, mm. */
    public static final double DEFAULT_MAX_DIST_TO_KEEP_CUMULATIVE = 3000;
    /** How close a new cumulative reading must be to an old one to replace it, mm. */
    public static final double DEFAULT_MIN_DIST_BETWEEN_CUMULATIVE = 50;
    /** The position of the device's sensor-interpretation task (ARIA's range devices use 50). */
    static final int TASK_POSITION = 50;

    private static final AtomicLong IDS = new AtomicLong();

    private final String name;
    private final String taskName;
    private final ArRangeBuffer current;
    private final ArRangeBuffer cumulative;
    private volatile List<ArSensorReading> rawReadings = List.of();
    private volatile ArRobot robot;
    private volatile double maxRange;
    private int maxSecondsToKeepCurrent = DEFAULT_MAX_SECONDS_TO_KEEP_CURRENT;
    private int maxSecondsToKeepCumulative = DEFAULT_MAX_SECONDS_TO_KEEP_CUMULATIVE;
    private double maxDistToKeepCumulative = DEFAULT_MAX_DIST_TO_KEEP_CUMULATIVE;
    private double minDistBetweenCumulative = DEFAULT_MIN_DIST_BETWEEN_CUMULATIVE;

    /**
     * A device with buffers of {@value #DEFAULT_CURRENT_BUFFER_SIZE} and
     * {@value #DEFAULT_CUMULATIVE_BUFFER_SIZE} readings.
     *
     * @param name     the device's name
     * @param maxRange its maximum range, mm
     */
    public ArRangeDevice(String name, double maxRange) {
        this(name, maxRange, DEFAULT_CURRENT_BUFFER_SIZE, DEFAULT_CUMULATIVE_BUFFER_SIZE);
    }

    /**
     * @param name                 the device's name
     * @param maxRange             its maximum range, mm
     * @param currentBufferSize    how many current readings it keeps
     * @param cumulativeBufferSize how many cumulative readings it keeps (0: none)
     */
    public ArRangeDevice(String name, double maxRange, int currentBufferSize, int cumulativeBufferSize) {
        if (name == null) {
            throw new IllegalArgumentException("null was supplied for name: a range device needs a name");
        }
        this.name = name;
        // tasks are named per device, so two devices of the same name do not replace each other's
        this.taskName = name + " range device #" + IDS.incrementAndGet();
        this.current = new ArRangeBuffer("current", currentBufferSize);
        this.cumulative = new ArRangeBuffer("cumulative", cumulativeBufferSize);
        this.maxRange = checkedMaxRange(maxRange);
    }

    /** @return the device's name */
    public String getName() {
        return name;
    }

    /**
     * Attaches the device to a robot, registering its per-cycle task there and removing it from the
     * robot it was attached to; {@link ArRobot#addRangeDevice} calls this.
     *
     * @param robot the robot, or null to detach
     */
    public synchronized void setRobot(ArRobot robot) {
        ArRobot old = this.robot;
        if (old != null) {
            old.remSensorInterpTask(taskName);
        }
        this.robot = robot;
        if (robot != null) {
            robot.addSensorInterpTask(taskName, TASK_POSITION, this::sensorInterp);
        }
    }

    /** @return the robot the device is attached to, or null */
    public ArRobot getRobot() {
        return robot;
    }

    /** @return the maximum range, mm */
    public double getMaxRange() {
        return maxRange;
    }

    /** @param maxRange the maximum range, mm, greater than 0 */
    public void setMaxRange(double maxRange) {
        this.maxRange = checkedMaxRange(maxRange);
    }

    private static double checkedMaxRange(double maxRange) {
        if (!(maxRange > 0) || Double.isInfinite(maxRange)) {
            throw new IllegalArgumentException(maxRange
                    + " was supplied for maxRange: it must be a finite number greater than 0");
        }
        return maxRange;
    }

    // ---- buffers ----

    /** @return how many current readings the device keeps */
    public synchronized int getCurrentBufferSize() {
        return current.getSize();
    }

    /** @param size how many current readings to keep, 0 or more; a smaller size evicts the oldest */
    public synchronized void setCurrentBufferSize(int size) {
        current.setSize(size);
    }

    /** @return how many cumulative readings the device keeps */
    public synchronized int getCumulativeBufferSize() {
        return cumulative.getSize();
    }

    /** @param size how many cumulative readings to keep, 0 or more; a smaller size evicts the oldest */
    public synchronized void setCumulativeBufferSize(int size) {
        cumulative.setSize(size);
    }

    /**
     * Adds a reading to both buffers, stamped with the simulated time and the robot's pose. It goes
     * into the cumulative buffer only within {@link #getMaxDistToKeepCumulative()} of the robot, and
     * there it replaces the readings closer than {@link #getMinDistBetweenCumulative()} to it.
     *
     * @param x the echo's global x, mm
     * @param y the echo's global y, mm
     */
    public synchronized void addReading(double x, double y) {
        addReading(x, y, robotPose(), nowMs());
    }

    /**
     * Adds a reading taken at a known pose and time: for devices that add many readings from one
     * cycle's state.
     *
     * @param x      the echo's global x, mm
     * @param y      the echo's global y, mm
     * @param pose   the robot's pose when it was taken
     * @param timeMs simulated time when it was taken
     */
    protected synchronized void addReading(double x, double y, ArPose pose, long timeMs) {
        ArPoseWithTime reading = new ArPoseWithTime(x, y, timeMs, pose);
        current.add(reading);
        if (cumulative.getSize() == 0
                || maxDistToKeepCumulative > 0 && reading.fartherThan(pose.getX(), pose.getY(), maxDistToKeepCumulative)) {
            return;
        }
        if (minDistBetweenCumulative > 0) {
            cumulative.removeWithin(x, y, minDistBetweenCumulative);
        }
        cumulative.add(reading);
    }

    /**
     * Adds a reading to the current buffer only: for devices whose readings say nothing lasting
     * ({@link ArBumpers}).
     *
     * @param x      the reading's global x, mm
     * @param y      the reading's global y, mm
     * @param pose   the robot's pose when it was taken
     * @param timeMs simulated time when it was taken
     */
    protected synchronized void addCurrentReading(double x, double y, ArPose pose, long timeMs) {
        current.add(new ArPoseWithTime(x, y, timeMs, pose));
    }

    /**
     * Replaces the current buffer with one scan's readings, as ARIA's laser redoes its current
     * buffer with each scan; the last of the list becomes the newest.
     *
     * @param xy     the readings' global positions, each {x, y}, mm
     * @param pose   the robot's pose when the scan was taken
     * @param timeMs the scan's simulated time
     */
    synchronized void replaceCurrent(List<double[]> xy, ArPose pose, long timeMs) {
        current.clear();
        for (double[] p : xy) {
            current.add(new ArPoseWithTime(p[0], p[1], timeMs, pose));
        }
    }

    /** @return the cumulative buffer, for devices of this package with rules of their own */
    ArRangeBuffer cumulativeBuffer() {
        return cumulative;
    }

    /** @return the current readings' positions, newest first, pruned first */
    public synchronized List<ArPose> getCurrentBuffer() {
        prune();
        return current.poses();
    }

    /** @return the cumulative readings' positions, newest first, pruned first */
    public synchronized List<ArPose> getCumulativeBuffer() {
        prune();
        return cumulative.poses();
    }

    /** Empties the current buffer. */
    public synchronized void clearCurrentReadings() {
        current.clear();
    }

    /** Empties the cumulative buffer. */
    public synchronized void clearCumulativeReadings() {
        cumulative.clear();
    }

    // ---- pruning rules ----

    /** @return how long current readings are kept, s; 0 or less: for ever */
    public synchronized int getMaxSecondsToKeepCurrent() {
        return maxSecondsToKeepCurrent;
    }

    /** @param seconds how long current readings are kept, s; 0 or less: for ever */
    public synchronized void setMaxSecondsToKeepCurrent(int seconds) {
        maxSecondsToKeepCurrent = seconds;
    }

    /** @return how long cumulative readings are kept, s; 0 or less: for ever */
    public synchronized int getMaxSecondsToKeepCumulative() {
        return maxSecondsToKeepCumulative;
    }

    /** @param seconds how long cumulative readings are kept, s; 0 or less: for ever */
    public synchronized void setMaxSecondsToKeepCumulative(int seconds) {
        maxSecondsToKeepCumulative = seconds;
    }

    /** @return how far from the robot cumulative readings are kept, mm; 0 or less: any distance */
    public synchronized double getMaxDistToKeepCumulative() {
        return maxDistToKeepCumulative;
    }

    /** @param mm how far from the robot cumulative readings are kept; 0 or less: any distance */
    public synchronized void setMaxDistToKeepCumulative(double mm) {
        maxDistToKeepCumulative = mm;
    }

    /** @return how close a new cumulative reading replaces an old one, mm; 0 or less: never */
    public synchronized double getMinDistBetweenCumulative() {
        return minDistBetweenCumulative;
    }

    /** @param mm how close a new cumulative reading replaces an old one; 0 or less: never */
    public synchronized void setMinDistBetweenCumulative(double mm) {
        minDistBetweenCumulative = mm;
    }

    // ---- queries ----

    /**
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @return the distance from the robot centre to the nearest current reading strictly inside the
     *         interval ({@link ArMath#angleBetween}), at most the maximum range; the maximum range if
     *         there is none
     */
    public double currentReadingPolar(double startAngle, double endAngle) {
        return currentReadingPolar(startAngle, endAngle, null);
    }

    /**
     * As {@link #currentReadingPolar(double, double)}, also giving the reading's angle.
     *
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @param angleOut   null, or an array whose element 0 receives the nearest reading's angle
     *                   relative to the robot's heading; left as it was if there is none
     * @return the distance, mm, or the maximum range
     */
    public synchronized double currentReadingPolar(double startAngle, double endAngle, double[] angleOut) {
        prune();
        return polar(current, startAngle, endAngle, angleOut);
    }

    /**
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @return the distance from the robot centre to the nearest cumulative reading strictly inside
     *         the interval, at most the maximum range; the maximum range if there is none
     */
    public double cumulativeReadingPolar(double startAngle, double endAngle) {
        return cumulativeReadingPolar(startAngle, endAngle, null);
    }

    /**
     * As {@link #cumulativeReadingPolar(double, double)}, also giving the reading's angle.
     *
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @param angleOut   null, or an array whose element 0 receives the nearest reading's angle
     *                   relative to the robot's heading; left as it was if there is none
     * @return the distance, mm, or the maximum range
     */
    public synchronized double cumulativeReadingPolar(double startAngle, double endAngle, double[] angleOut) {
        prune();
        return polar(cumulative, startAngle, endAngle, angleOut);
    }

    private double polar(ArRangeBuffer buffer, double start, double end, double[] angleOut) {
        if (angleOut != null && angleOut.length == 0) {
            throw new IllegalArgumentException("an empty array was supplied for angleOut: it needs one element");
        }
        ArRangeBuffer.Closest c = buffer.closestPolar(start, end, robotPose());
        if (c == null) {
            return maxRange;
        }
        if (angleOut != null) {
            angleOut[0] = c.angle();
        }
        return Math.min(c.distance(), maxRange);
    }

    /**
     * The nearest current reading inside a box around the robot (ARIA's {@code currentReadingBox}).
     *
     * @param x1 one corner's x, mm, in the robot's frame (x forward)
     * @param y1 one corner's y, mm, in the robot's frame (y left)
     * @param x2 the opposite corner's x, mm
     * @param y2 the opposite corner's y, mm
     * @return the distance from the robot centre to the nearest current reading in the box (edges
     *         included), at most the maximum range; the maximum range if there is none
     */
    public double currentReadingBox(double x1, double y1, double x2, double y2) {
        return currentReadingBox(x1, y1, x2, y2, null);
    }

    /**
     * As {@link #currentReadingBox(double, double, double, double)}, also giving the reading.
     *
     * @param x1         one corner's x, mm, robot frame
     * @param y1         one corner's y, mm, robot frame
     * @param x2         the opposite corner's x, mm
     * @param y2         the opposite corner's y, mm
     * @param readingPos null, or a pose set to the nearest reading in the robot's frame; set to
     *                   (0, 0, 0) if there is none, as ARIA sets it
     * @return the distance, mm, or the maximum range
     */
    public synchronized double currentReadingBox(double x1, double y1, double x2, double y2, ArPose readingPos) {
        prune();
        return box(current, x1, y1, x2, y2, readingPos);
    }

    /**
     * The nearest cumulative reading inside a box around the robot (ARIA's
     * {@code cumulativeReadingBox}).
     *
     * @param x1 one corner's x, mm, robot frame
     * @param y1 one corner's y, mm, robot frame
     * @param x2 the opposite corner's x, mm
     * @param y2 the opposite corner's y, mm
     * @return the distance from the robot centre, at most the maximum range; the maximum range if
     *         there is none
     */
    public double cumulativeReadingBox(double x1, double y1, double x2, double y2) {
        return cumulativeReadingBox(x1, y1, x2, y2, null);
    }

    /**
     * As {@link #cumulativeReadingBox(double, double, double, double)}, also giving the reading.
     *
     * @param x1         one corner's x, mm, robot frame
     * @param y1         one corner's y, mm, robot frame
     * @param x2         the opposite corner's x, mm
     * @param y2         the opposite corner's y, mm
     * @param readingPos null, or a pose set to the nearest reading in the robot's frame; (0, 0, 0)
     *                   if there is none
     * @return the distance, mm, or the maximum range
     */
    public synchronized double cumulativeReadingBox(double x1, double y1, double x2, double y2, ArPose readingPos) {
        prune();
        return box(cumulative, x1, y1, x2, y2, readingPos);
    }

    private double box(ArRangeBuffer buffer, double x1, double y1, double x2, double y2, ArPose readingPos) {
        ArPose closest = buffer.closestBox(x1, y1, x2, y2, robotPose());
        ArPose found = closest == null ? new ArPose() : closest;
        if (readingPos != null) {
            readingPos.setPose(found.getX(), found.getY(), found.getTh());
        }
        return closest == null ? maxRange : Math.min(Math.hypot(found.getX(), found.getY()), maxRange);
    }

    /**
     * Moves the buffered readings by a rigid motion (ARIA's {@code applyTransform}):
     * {@link ArRobot#moveTo} moves them with the robot, so they keep their place relative to it.
     *
     * @param trans        the motion
     * @param doCumulative whether the cumulative buffer moves too (the current buffer always does)
     */
    public synchronized void applyTransform(ArTransform trans, boolean doCumulative) {
        current.applyTransform(trans);
        if (doCumulative) {
            cumulative.applyTransform(trans);
        }
        for (ArSensorReading r : rawReadings) {
            r.applyTransform(trans);
        }
    }

    /**
     * @return the device's latest readings as it took them (ARIA's {@code getRawReadings}): the
     *         laser's latest scan, the sonar readings new in the latest cycle; empty for a device
     *         that keeps none
     */
    public List<ArSensorReading> getRawReadings() {
        return rawReadings;
    }

    /** @param readings the device's latest readings, kept as they are (callers pass a fresh list) */
    protected void setRawReadings(List<ArSensorReading> readings) {
        rawReadings = List.copyOf(readings);
    }

    // ---- the cycle ----

    /**
     * Takes the device's new readings for this cycle, with {@link #addReading}; runs in the robot's
     * cycle, under its lock, before pruning. This device has none of its own.
     */
    protected void processReadings() {
    }

    private synchronized void sensorInterp() {
        processReadings();
        prune();
    }

    private void prune() {
        RobotState s = cycleState();
        if (s == null) {
            return;
        }
        if (maxSecondsToKeepCurrent > 0) {
            current.removeOlderThan(s.timeMs(), maxSecondsToKeepCurrent * 1000L);
        }
        if (maxSecondsToKeepCumulative > 0) {
            cumulative.removeOlderThan(s.timeMs(), maxSecondsToKeepCumulative * 1000L);
        }
        if (maxDistToKeepCumulative > 0) {
            cumulative.removeFartherThan(robotPose(), maxDistToKeepCumulative);
        }
    }

    /** @return the state of the robot's latest cycle, or null without a robot or before any state */
    RobotState cycleState() {
        ArRobot r = robot;
        return r == null ? null : r.currentState();
    }

    /**
     * @return the robot's pose ({@link ArRobot#getPose()}, moved by {@link ArRobot#moveTo}) in its
     *         latest cycle, or the origin
     */
    ArPose robotPose() {
        ArRobot r = robot;
        return r == null || r.currentState() == null ? new ArPose() : r.getPose();
    }

    private long nowMs() {
        RobotState s = cycleState();
        return s == null ? 0 : s.timeMs();
    }
}
