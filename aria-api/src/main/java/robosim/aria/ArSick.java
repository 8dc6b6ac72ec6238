package robosim.aria;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Logger;
import robosim.protocol.Command;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotState;
import robosim.protocol.RobotParameters;

/**
 * A SICK LMS200 laser as a range device (ARIA 2.x's {@code ArSick}), named {@code laser}: it scans
 * 180°, from 90° right to 90° left of its mounting heading, at 1° (181 readings) or 0.5° (361)
 * steps, up to 8000 mm. Each cycle the robot's latest scan becomes the raw readings
 * ({@link #getRawReadings()}), and the readings below the maximum range (the ones that hit
 * something) become the current buffer, which holds the latest scan only, as ARIA's
 * {@code ArLaser.cpp} redoes it with each scan (a cycle without a scan leaves it as it is). The
 * cumulative buffer follows ARIA's laser rules ({@code ArLaser.cpp}) with the defaults of ARIA's
 * LMS200 driver ({@code ArLMS2xx.cpp}): readings enter within {@value #DEFAULT_MAX_INSERT_DIST_CUMULATIVE}
 * mm of the laser and not within {@value #DEFAULT_MIN_DIST_BETWEEN_CUMULATIVE} mm of a kept reading;
 * they are kept {@value #DEFAULT_MAX_SECONDS_TO_KEEP_CUMULATIVE} s and within
 * {@value #DEFAULT_MAX_DIST_TO_KEEP_LASER_CUMULATIVE} mm of the robot; and every
 * {@value #DEFAULT_CUMULATIVE_CLEAN_INTERVAL_MS} ms the beams clear the kept readings they pass within
 * {@value #DEFAULT_CUMULATIVE_CLEAN_DIST} mm of. The mounting pose is the parameter file's
 * {@code LaserX/LaserY/LaserTh}.
 *
 * <pre>{@code
 * ArSick sick = new ArSick();
 * robot.addRangeDevice(sick);
 * robot.blockingConnect();
 * if (!sick.blockingConnect()) throw new IllegalStateException(sick.getConnectionError());
 * }</pre>
 *
 * <p>Unlike ARIA's, {@link #blockingConnect()} does not wait for the first scan: it switches the
 * laser on with the current step's requests, and scans arrive from the next step's state.
 */
public class ArSick extends ArRangeDevice {
    /** A SICK LMS200's range, mm. */
    public static final double DEFAULT_MAX_RANGE = RobotParameters.DEFAULT_LASER_MAX_RANGE;
    private static final Logger LOG = Logger.getLogger(ArSick.class.getName());
    /** One whole scan at 0.5°. */
    private static final int SCAN_READINGS = 361;
    private static final int CUMULATIVE_READINGS = 200;
    /** ARIA's LMS200 default: readings farther than this from the laser do not enter the cumulative buffer, mm. */
    public static final double DEFAULT_MAX_INSERT_DIST_CUMULATIVE = LaserCumulative.DEFAULT_MAX_INSERT_DIST;
    /** ARIA's LMS200 default: a reading closer than this to a cumulative one does not enter, mm. */
    public static final double DEFAULT_MIN_DIST_BETWEEN_CUMULATIVE = 200;
    /** ARIA's LMS200 default: how long cumulative readings are kept, s. */
    public static final int DEFAULT_MAX_SECONDS_TO_KEEP_CUMULATIVE = 30;
    /** ARIA's LMS200 default: how far from the robot cumulative readings are kept, mm. */
    public static final double DEFAULT_MAX_DIST_TO_KEEP_LASER_CUMULATIVE = 6000;
    /** ARIA's LMS200 default: how close to a beam a cumulative reading is cleared, mm. */
    public static final double DEFAULT_CUMULATIVE_CLEAN_DIST = LaserCumulative.DEFAULT_CLEAN_DIST;
    /** ARIA's LMS200 default: how often the beams clear the cumulative buffer, ms. */
    public static final long DEFAULT_CUMULATIVE_CLEAN_INTERVAL_MS = LaserCumulative.DEFAULT_CLEAN_INTERVAL_MS;

    private final LaserCumulative cumulativeRules = new LaserCumulative();

    private volatile double increment = 1.0;
    private volatile boolean maxRangeChosen;
    private volatile boolean connected;
    private volatile String connectionError;
    private volatile int[] rawScan = new int[0];

    /** A laser with buffers of 361 readings (a whole scan at 0.5°) and 200. */
    public ArSick() {
        this(SCAN_READINGS, CUMULATIVE_READINGS);
    }

    /**
     * @param currentBufferSize    how many current readings it keeps
     * @param cumulativeBufferSize how many cumulative readings it keeps (0: none)
     */
    public ArSick(int currentBufferSize, int cumulativeBufferSize) {
        super("laser", DEFAULT_MAX_RANGE, currentBufferSize, cumulativeBufferSize);
        // ARIA's ArLaser keeps current readings until the next scan replaces them
        setMaxSecondsToKeepCurrent(0);
        setMaxSecondsToKeepCumulative(DEFAULT_MAX_SECONDS_TO_KEEP_CUMULATIVE);
        setMaxDistToKeepCumulative(DEFAULT_MAX_DIST_TO_KEEP_LASER_CUMULATIVE);
        setMinDistBetweenCumulative(DEFAULT_MIN_DIST_BETWEEN_CUMULATIVE);
    }

    /** @return how far from the laser a reading may be to enter the cumulative buffer, mm; 1 or less: any */
    public synchronized double getMaxInsertDistCumulative() {
        return cumulativeRules.maxInsertDist;
    }

    /** @param mm how far from the laser a reading may be to enter the cumulative buffer; 1 or less: any */
    public synchronized void setMaxInsertDistCumulative(double mm) {
        cumulativeRules.maxInsertDist = mm;
    }

    /** @return how close to a beam a cumulative reading is cleared, mm; below 1: never */
    public synchronized double getCumulativeCleanDist() {
        return cumulativeRules.cleanDist;
    }

    /** @param mm how close to a beam a cumulative reading is cleared; below 1: never */
    public synchronized void setCumulativeCleanDist(double mm) {
        cumulativeRules.cleanDist = mm;
    }

    /** @return how often the beams clear the cumulative buffer, simulated ms; 0 or less: every scan */
    public synchronized long getCumulativeCleanInterval() {
        return cumulativeRules.cleanIntervalMs;
    }

    /** @param ms how often the beams clear the cumulative buffer, simulated ms; 0 or less: every scan */
    public synchronized void setCumulativeCleanInterval(long ms) {
        cumulativeRules.cleanIntervalMs = ms;
    }

    /**
     * Attaches the laser to a robot; unless {@link #setMaxRange} was called, its maximum range
     * becomes the robot's parameter-file {@code LaserMaxRange}.
     *
     * @param robot the robot, or null to detach
     */
    @Override
    public synchronized void setRobot(ArRobot robot) {
        super.setRobot(robot);
        if (robot != null && !maxRangeChosen) {
            super.setMaxRange(robot.getParameters().laserMaxRange());
        }
    }

    /**
     * Sets the maximum range; sent to the Environment at once if the laser is connected.
     *
     * @param maxRange mm, greater than 0
     */
    @Override
    public void setMaxRange(double maxRange) {
        super.setMaxRange(maxRange);
        maxRangeChosen = true;
        reconfigure();
    }

    /** @return the angle between readings, degrees: 1 or 0.5 */
    public double getIncrement() {
        return increment;
    }

    /**
     * Sets the angle between readings; sent to the Environment at once if the laser is connected.
     *
     * @param degrees 1 (181 readings a scan) or 0.5 (361)
     */
    public void setIncrement(double degrees) {
        Command.ConfigureLaser.requireIncrement("increment", degrees);
        increment = degrees;
        reconfigure();
    }

    /**
     * Switches the laser on: needs the laser attached to a robot that is connected.
     *
     * @return true if the request was sent; otherwise {@link #getConnectionError()} says why
     */
    public synchronized boolean blockingConnect() {
        ArRobot robot = getRobot();
        if (robot == null) {
            return fail("the laser is attached to no robot: attach it with ArRobot.addRangeDevice first");
        }
        if (!robot.isConnected()) {
            return fail("robot " + robot.getName() + " is not connected: connect the robot first");
        }
        robot.send(new Command.ConfigureLaser(true, increment, getMaxRange()));
        connected = true;
        connectionError = null;
        return true;
    }

    private boolean fail(String reason) {
        connectionError = reason;
        LOG.warning(() -> "laser could not connect: " + reason);
        return false;
    }

    /** Switches the laser off; scans stop from the next step's state. */
    public synchronized void disconnect() {
        ArRobot robot = getRobot();
        if (connected && robot != null && robot.isConnected()) {
            robot.send(new Command.ConfigureLaser(false, increment, getMaxRange()));
        }
        connected = false;
    }

    /** @return whether the laser was switched on and its robot is still connected */
    public boolean isConnected() {
        ArRobot robot = getRobot();
        return connected && robot != null && robot.isConnected();
    }

    /** @return why the last {@link #blockingConnect()} failed, or null */
    public String getConnectionError() {
        return connectionError;
    }

    private synchronized void reconfigure() {
        if (isConnected()) {
            getRobot().send(new Command.ConfigureLaser(true, increment, getMaxRange()));
        }
    }

    /**
     * @return the latest scan's readings, from the laser's right to its left: each one's sensor
     *         pose is the mounting pose turned by the beam's angle; empty when the laser is off
     */
    @Override
    public List<ArSensorReading> getRawReadings() {
        return super.getRawReadings();
    }

    /** @return the latest scan's ranges, mm from the laser, from its right to its left; a copy */
    public int[] getRawScan() {
        return rawScan.clone();
    }

    /**
     * Turns the robot's latest scan into raw readings; those below the maximum range become the
     * current buffer, and the scan is taken into the cumulative buffer by ARIA's laser rules.
     */
    @Override
    protected void processReadings() {
        ArRobot robot = getRobot();
        RobotState s = cycleState();
        if (robot == null || s == null) {
            return;
        }
        int[] scan = s.get(LaserReading.PART).ranges().clone();
        RobotParameters p = robot.getParameters();
        ArPose pose = robotPose();
        // the step follows from the scan's length, so a scan taken before a change of increment
        // is still read right
        double step = scan.length > 1 ? 180.0 / (scan.length - 1) : 0;
        double max = getMaxRange();
        List<ArSensorReading> readings = new ArrayList<>(scan.length);
        List<double[]> hits = new ArrayList<>(scan.length);
        for (int i = 0; i < scan.length; i++) {
            ArSensorReading r = new ArSensorReading(p.laserX(), p.laserY(), p.laserTh() - 90 + i * step, (int) max);
            r.newData(scan[i], pose, robot.getCounter(), s.timeMs());
            readings.add(r);
            if (scan[i] < max) {
                hits.add(new double[] {r.getX(), r.getY()});
            }
        }
        rawScan = scan;
        setRawReadings(readings);
        if (scan.length > 0) {
            replaceCurrent(hits, pose, s.timeMs());
            cumulativeRules.take(cumulativeBuffer(), readings, max, getMinDistBetweenCumulative(), pose, s.timeMs());
        }
    }
}
