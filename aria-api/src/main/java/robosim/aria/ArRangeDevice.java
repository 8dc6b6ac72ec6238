package robosim.aria;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.ReentrantLock;
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
 *
 * <p>Each call is atomic on its own. {@link #lockDevice()} (ARIA's device lock) holds off the
 * device's update in the robot's cycle, so that several calls read one cycle's readings; the cycle
 * holds the robot's lock while it waits for it, so, as in ARIA, a thread holding the device lock
 * must not wait for the robot's.
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
    /** ARIA's {@code ArMutex::STATUS_FAILED}: what {@link #unlockDevice()} answers when the thread does not hold the lock. */
    public static final int STATUS_FAILED = 2;
    /** ARIA's {@code ArMutex::STATUS_ALREADY_LOCKED}: what {@link #tryLockDevice()} answers when another thread holds the lock. */
    public static final int STATUS_ALREADY_LOCKED = 3;

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
    private double minDistBetweenCurrent;
    private double maxInsertDistCumulative;
    private final boolean locationDependent;
    private final ReentrantLock deviceLock = new ReentrantLock();

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
        this(name, maxRange, currentBufferSize, cumulativeBufferSize, false);
    }

    private ArRangeDevice(String name, double maxRange, int currentBufferSize, int cumulativeBufferSize,
            boolean locationDependent) {
        if (name == null) {
            throw new IllegalArgumentException("null was supplied for name: a range device needs a name");
        }
        this.name = name;
        this.locationDependent = locationDependent;
        // tasks are named per device, so two devices of the same name do not replace each other's
        this.taskName = name + " range device #" + IDS.incrementAndGet();
        this.current = new ArRangeBuffer("current", currentBufferSize);
        this.cumulative = new ArRangeBuffer("cumulative", cumulativeBufferSize);
        this.maxRange = checkedMaxRange(maxRange);
    }

    /**
     * ARIA's constructor ({@code ArRangeDevice(currentBufferSize, cumulativeBufferSize, name,
     * maxRange, maxSecondsToKeepCurrent, maxSecondsToKeepCumulative, maxDistToKeepCumulative,
     * locationDependent)}, ArRangeDevice.cpp), with ARIA's rules: white space in the name becomes
     * '_'; the minimum distances between readings and the maximum insertion distance start at 0 (off);
     * times and distances of 0 or less keep readings for ever and at any distance.
     *
     * @param currentBufferSize          how many current readings it keeps
     * @param cumulativeBufferSize       how many cumulative readings it keeps
     * @param name                       the device's name
     * @param maxRange                   its maximum range, mm, greater than 0
     * @param maxSecondsToKeepCurrent    how long current readings are kept, s
     * @param maxSecondsToKeepCumulative how long cumulative readings are kept, s
     * @param maxDistToKeepCumulative    how far from the robot cumulative readings are kept, mm
     * @param locationDependent          whether the device's readings depend on where the robot
     *                                   thinks it is (a map's forbidden lines); see {@link #isLocationDependent()}
     */
    public ArRangeDevice(int currentBufferSize, int cumulativeBufferSize, String name, int maxRange,
            int maxSecondsToKeepCurrent, int maxSecondsToKeepCumulative, double maxDistToKeepCumulative,
            boolean locationDependent) {
        this(name == null ? null : name.replaceAll("[ \\t\\n\\x0B\\f\\r]", "_"), maxRange, currentBufferSize,
                cumulativeBufferSize, locationDependent);
        this.maxSecondsToKeepCurrent = maxSecondsToKeepCurrent;
        this.maxSecondsToKeepCumulative = maxSecondsToKeepCumulative;
        this.maxDistToKeepCumulative = maxDistToKeepCumulative;
        this.minDistBetweenCumulative = 0;
    }

    /**
     * ARIA's constructor with its defaults: readings kept for ever and at any distance, not location
     * dependent.
     *
     * @param currentBufferSize    how many current readings it keeps
     * @param cumulativeBufferSize how many cumulative readings it keeps
     * @param name                 the device's name
     * @param maxRange             its maximum range, mm
     */
    public ArRangeDevice(int currentBufferSize, int cumulativeBufferSize, String name, int maxRange) {
        this(currentBufferSize, cumulativeBufferSize, name, maxRange, 0, 0, 0, false);
    }

    /**
     * ARIA's constructor with its defaults from {@code maxSecondsToKeepCumulative} on.
     *
     * @param currentBufferSize       how many current readings it keeps
     * @param cumulativeBufferSize    how many cumulative readings it keeps
     * @param name                    the device's name
     * @param maxRange                its maximum range, mm
     * @param maxSecondsToKeepCurrent how long current readings are kept, s
     */
    public ArRangeDevice(int currentBufferSize, int cumulativeBufferSize, String name, int maxRange,
            int maxSecondsToKeepCurrent) {
        this(currentBufferSize, cumulativeBufferSize, name, maxRange, maxSecondsToKeepCurrent, 0, 0, false);
    }

    /**
     * ARIA's constructor with its defaults from {@code maxDistToKeepCumulative} on.
     *
     * @param currentBufferSize          how many current readings it keeps
     * @param cumulativeBufferSize       how many cumulative readings it keeps
     * @param name                       the device's name
     * @param maxRange                   its maximum range, mm
     * @param maxSecondsToKeepCurrent    how long current readings are kept, s
     * @param maxSecondsToKeepCumulative how long cumulative readings are kept, s
     */
    public ArRangeDevice(int currentBufferSize, int cumulativeBufferSize, String name, int maxRange,
            int maxSecondsToKeepCurrent, int maxSecondsToKeepCumulative) {
        this(currentBufferSize, cumulativeBufferSize, name, maxRange, maxSecondsToKeepCurrent,
                maxSecondsToKeepCumulative, 0, false);
    }

    /**
     * ARIA's constructor, not location dependent.
     *
     * @param currentBufferSize          how many current readings it keeps
     * @param cumulativeBufferSize       how many cumulative readings it keeps
     * @param name                       the device's name
     * @param maxRange                   its maximum range, mm
     * @param maxSecondsToKeepCurrent    how long current readings are kept, s
     * @param maxSecondsToKeepCumulative how long cumulative readings are kept, s
     * @param maxDistToKeepCumulative    how far from the robot cumulative readings are kept, mm
     */
    public ArRangeDevice(int currentBufferSize, int cumulativeBufferSize, String name, int maxRange,
            int maxSecondsToKeepCurrent, int maxSecondsToKeepCumulative, double maxDistToKeepCumulative) {
        this(currentBufferSize, cumulativeBufferSize, name, maxRange, maxSecondsToKeepCurrent,
                maxSecondsToKeepCumulative, maxDistToKeepCumulative, false);
    }

    /**
     * ARIA's {@code isLocationDependent}: whether the device's readings depend on where the robot
     * thinks it is (ARIA's map-based devices); set by ARIA's constructor, false otherwise.
     *
     * @return whether the device is location dependent
     */
    public boolean isLocationDependent() {
        return locationDependent;
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
     * ARIA's {@code addReading(x, y, wasAdded)}: as {@link #addReading(double, double)}, telling
     * whether the reading went into the current buffer (it does not when
     * {@link #getMinDistBetweenCurrent()} refreshed an older one instead).
     *
     * @param x        the echo's global x, mm
     * @param y        the echo's global y, mm
     * @param wasAdded null, or an array whose element 0 receives whether it was added
     */
    public synchronized void addReading(double x, double y, boolean[] wasAdded) {
        boolean added = addReadingAt(x, y, robotPose(), nowMs());
        if (wasAdded != null) {
            wasAdded[0] = added;
        }
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
        addReadingAt(x, y, pose, timeMs);
    }

    /** @return whether the reading went into the current buffer */
    private boolean addReadingAt(double x, double y, ArPose pose, long timeMs) {
        ArPoseWithTime reading = new ArPoseWithTime(x, y, timeMs, pose);
        boolean added = !(minDistBetweenCurrent > 0 && current.refreshWithin(x, y, minDistBetweenCurrent, timeMs));
        if (added) {
            current.add(reading);
        }
        if (cumulative.getSize() == 0
                || maxDistToKeepCumulative > 0 && reading.fartherThan(pose.getX(), pose.getY(), maxDistToKeepCumulative)
                || maxInsertDistCumulative > 0 && robot != null
                        && reading.fartherThan(pose.getX(), pose.getY(), maxInsertDistCumulative)) {
            return added;
        }
        if (minDistBetweenCumulative > 0) {
            cumulative.removeWithin(x, y, minDistBetweenCumulative);
        }
        cumulative.add(reading);
        return added;
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

    /**
     * ARIA's {@code getCurrentReadings}: the current readings with their times, newest first, pruned
     * first.
     *
     * @return a copy of the buffer
     */
    public synchronized List<ArPoseWithTime> getCurrentReadings() {
        prune();
        return current.readings();
    }

    /**
     * ARIA's {@code getCumulativeReadings}: the cumulative readings with their times, newest first,
     * pruned first.
     *
     * @return a copy of the buffer
     */
    public synchronized List<ArPoseWithTime> getCumulativeReadings() {
        prune();
        return cumulative.readings();
    }

    /**
     * ARIA's {@code clearCumulativeOlderThan}: removes the cumulative readings taken more than
     * {@code milliSeconds} before now (simulated time); exactly that old stays.
     *
     * @param milliSeconds the age, ms
     */
    public synchronized void clearCumulativeOlderThan(int milliSeconds) {
        cumulative.removeOlderThan(nowMs(), milliSeconds);
    }

    /**
     * ARIA's {@code clearCumulativeOlderThanSeconds}: {@link #clearCumulativeOlderThan} of
     * {@code seconds · 1000} ms.
     *
     * @param seconds the age, s
     */
    public synchronized void clearCumulativeOlderThanSeconds(int seconds) {
        clearCumulativeOlderThan(seconds * 1000);
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

    /**
     * @return ARIA's {@code getMinDistBetweenCurrent}: a new current reading closer than this to an
     *         older one refreshes the older one's time instead of being added; 0 (ARIA's default): off
     */
    public synchronized double getMinDistBetweenCurrent() {
        return minDistBetweenCurrent;
    }

    /** @param mm ARIA's {@code setMinDistBetweenCurrent}: see {@link #getMinDistBetweenCurrent()}; 0 or less: off */
    public synchronized void setMinDistBetweenCurrent(double mm) {
        minDistBetweenCurrent = mm;
    }

    /**
     * @return ARIA's {@code getMaxInsertDistCumulative}: a reading farther than this from the robot
     *         goes into the current buffer only, not the cumulative one (for a device with a robot);
     *         0 (ARIA's default): off. A laser measures it from the laser, 3000 mm by default, and
     *         takes 1 or less for off
     */
    public synchronized double getMaxInsertDistCumulative() {
        return maxInsertDistCumulative;
    }

    /** @param mm ARIA's {@code setMaxInsertDistCumulative}: see {@link #getMaxInsertDistCumulative()}; 0 or less: off */
    public synchronized void setMaxInsertDistCumulative(double mm) {
        maxInsertDistCumulative = mm;
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

    /**
     * ARIA's {@code getAdjustedRawReadings}: the raw readings corrected for the robot's odometry
     * delay. ARIA makes them only for a robot with an odometry delay; RoboSim's readings and poses
     * come from the same step, with no delay, so, as ARIA answers then, there are none.
     *
     * @return null
     */
    public List<ArSensorReading> getAdjustedRawReadings() {
        return null;
    }

    /** @param readings the device's latest readings, kept as they are (callers pass a fresh list) */
    protected void setRawReadings(List<ArSensorReading> readings) {
        rawReadings = List.copyOf(readings);
    }

    // ---- the device lock ----

    /**
     * ARIA's {@code lockDevice}: holds off the device's update in the robot's cycle until
     * {@link #unlockDevice()}; the lock is reentrant, as ARIA's is.
     *
     * @return 0
     */
    public int lockDevice() {
        deviceLock.lock();
        return 0;
    }

    /** @return 0 if the lock was taken, {@link #STATUS_ALREADY_LOCKED} if another thread holds it (ARIA's {@code tryLockDevice}) */
    public int tryLockDevice() {
        return deviceLock.tryLock() ? 0 : STATUS_ALREADY_LOCKED;
    }

    /** @return 0, or {@link #STATUS_FAILED} if the calling thread does not hold the lock (ARIA's {@code unlockDevice}) */
    public int unlockDevice() {
        if (!deviceLock.isHeldByCurrentThread()) {
            return STATUS_FAILED;
        }
        deviceLock.unlock();
        return 0;
    }

    /** @return as {@link #lockDevice()} (ARIA's {@code lock}) */
    public int lock() {
        return lockDevice();
    }

    /** @return as {@link #tryLockDevice()} (ARIA's {@code tryLock}) */
    public int tryLock() {
        return tryLockDevice();
    }

    /** @return as {@link #unlockDevice()} (ARIA's {@code unlock}) */
    public int unlock() {
        return unlockDevice();
    }

    // ---- logging ----

    /**
     * ARIA's {@code logConfig}: one line with the device's name and settings, to {@link ArLog}.
     *
     * @param level  the line's level
     * @param prefix text before the name
     */
    public synchronized void logConfig(ArLog.LogLevel level, String prefix) {
        ArLog.log(level, "%s%s MaxRange=%d MaxSecondsToKeepCurrent=%d MinDistBetweenCurrent=%s "
                + "MaxSecondsToKeepCumulative=%d MaxDistToKeepCumulative=%s MinDistBetweenCumulative=%s "
                + "MaxInsertDistCumulative=%s IsLocationDependent=%d HaveRawReadings=%d",
                prefix, name, Math.round(maxRange), maxSecondsToKeepCurrent, g(minDistBetweenCurrent),
                maxSecondsToKeepCumulative, g(maxDistToKeepCumulative), g(minDistBetweenCumulative),
                g(getMaxInsertDistCumulative()), locationDependent ? 1 : 0, rawReadings.isEmpty() ? 0 : 1);
    }

    /** ARIA's {@code logConfig()} with its defaults: level Normal, no prefix. */
    public void logConfig() {
        logConfig(ArLog.Normal, "");
    }

    /**
     * ARIA's {@code logData}: the buffers' readings, then the raw readings' ranges if there are any,
     * to {@link ArLog}.
     *
     * @param level  the lines' level
     * @param prefix text before the name
     */
    public synchronized void logData(ArLog.LogLevel level, String prefix) {
        prune();
        logBuffer(level, prefix, "Current", current.readings());
        logBuffer(level, prefix, "Cumulative", cumulative.readings());
        List<ArSensorReading> raw = rawReadings;
        if (!raw.isEmpty()) {
            ArPose p = robotPose();
            StringBuilder ranges = new StringBuilder();
            for (ArSensorReading r : raw) {
                ranges.append(r.getRange()).append(' ');
            }
            ArLog.log(level, "%s%s Raw: %d CurrentRobotPose: (%.0f, %.0f) Ranges: %s", prefix, name, raw.size(),
                    p.getX(), p.getY(), ranges);
        }
    }

    /** ARIA's {@code logData()} with its defaults: level Normal, no prefix. */
    public void logData() {
        logData(ArLog.Normal, "");
    }

    private void logBuffer(ArLog.LogLevel level, String prefix, String which, List<ArPoseWithTime> readings) {
        StringBuilder b = new StringBuilder();
        for (ArPoseWithTime r : readings) {
            b.append(String.format(java.util.Locale.ROOT, "(%.0f, %.0f) ", r.x(), r.y()));
        }
        ArLog.log(level, "%s%s %s: %d readings: %s", prefix, name, which, readings.size(), b);
    }

    private static String g(double v) {
        return String.format(java.util.Locale.ROOT, "%g", v);
    }

    // ---- the cycle ----

    /**
     * Takes the device's new readings for this cycle, with {@link #addReading}; runs in the robot's
     * cycle, under its lock, before pruning. This device has none of its own.
     */
    protected void processReadings() {
    }

    private void sensorInterp() {
        deviceLock.lock();
        try {
            synchronized (this) {
                processReadings();
                prune();
            }
        } finally {
            deviceLock.unlock();
        }
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
