package robosim.aria;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.protocol.Command;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotState;

/**
 * ARIA's {@code ArLMS2xx}: a SICK LMS200 on the robot, the laser RoboSim simulates. Its settings are
 * ARIA's (ArLMS2xx.cpp): a field of view of {@code 180} or {@code 100} degrees, readings every
 * degree ({@code one}) or half degree ({@code half}), units {@code 1mm}, {@code 1cm} or {@code 10cm}
 * (the ranges are rounded to them), reflector bits {@code 1ref}, {@code 2ref} or {@code 3ref}, and a
 * starting baud rate, which a simulated laser keeps without use. It scans from its right to its left
 * (the other way when {@link #setFlipped flipped}), up to the robot's parameter-file
 * {@code LaserMaxRange} (a real LMS200's 8 m), from the parameter file's {@code LaserX/LaserY/LaserTh}
 * unless {@link #setSensorPosition} says otherwise.
 *
 * <p>Each cycle the robot's latest scan becomes the raw readings ({@link #getRawReadings()}); the
 * readings below the maximum range (the ones that hit something), within the field of view and not
 * ignored, become the current buffer, which holds the latest scan only; the cumulative buffer
 * follows ARIA's laser rules ({@code ArLaser.cpp}) with the LMS200's defaults: readings enter within
 * {@value #DEFAULT_MAX_INSERT_DIST_CUMULATIVE} mm of the laser and not within
 * {@value #DEFAULT_MIN_DIST_BETWEEN_CUMULATIVE} mm of a kept one; they are kept
 * {@value #DEFAULT_MAX_SECONDS_TO_KEEP_CUMULATIVE} s and within
 * {@value #DEFAULT_MAX_DIST_TO_KEEP_LASER_CUMULATIVE} mm of the robot; and every
 * {@value #DEFAULT_CUMULATIVE_CLEAN_INTERVAL_MS} ms the beams clear the kept readings they pass within
 * {@value #DEFAULT_CUMULATIVE_CLEAN_DIST} mm of.
 *
 * <p>Connecting does not wait for the first scan: it switches the laser on with the current step's
 * requests, and scans arrive from the next step's state.
 */
public class ArLMS2xx extends ArLaser {
    /** A SICK LMS200's range, mm. */
    public static final double DEFAULT_MAX_RANGE = RobotParameters.DEFAULT_LASER_MAX_RANGE;
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
    /** One whole scan at 0.5°. */
    static final int SCAN_READINGS = 361;
    static final int CUMULATIVE_READINGS = 200;

    private volatile boolean maxRangeChosen;
    private volatile boolean connected;
    private volatile String connectionError;
    private volatile int[] rawScan = new int[0];

    /** @param laserNumber its number on the robot, from 1; named {@code lms2xx_N} */
    public ArLMS2xx(int laserNumber) {
        this(laserNumber, "lms2xx", true);
    }

    /**
     * @param laserNumber             its number on the robot, from 1
     * @param name                    its name
     * @param appendLaserNumberToName whether {@code _N} is added to the name, as ARIA adds it
     */
    public ArLMS2xx(int laserNumber, String name, boolean appendLaserNumberToName) {
        this(laserNumber, appendLaserNumberToName ? name + "_" + laserNumber : name, SCAN_READINGS, CUMULATIVE_READINGS);
    }

    /** A laser with buffers of the sizes given, for {@link ArSick}. */
    ArLMS2xx(int laserNumber, String name, int currentBufferSize, int cumulativeBufferSize) {
        super(laserNumber, name, DEFAULT_MAX_RANGE, currentBufferSize, cumulativeBufferSize);
        Map<String, Double> degrees = new LinkedHashMap<>();
        degrees.put("180", 180.0);
        degrees.put("100", 100.0);
        laserAllowDegreesChoices("180", degrees);
        Map<String, Double> increments = new LinkedHashMap<>();
        increments.put("one", 1.0);
        increments.put("half", 0.5);
        laserAllowIncrementChoices("one", increments);
        laserAllowUnitsChoices("1mm", List.of("1mm", "1cm", "10cm"));
        laserAllowSetPowerControlled(false);
        laserAllowReflectorBitsChoices("1ref", List.of("1ref", "2ref", "3ref"));
        laserAllowStartingBaudChoices("9600", List.of("9600", "19200", "38400"));
        laserAllowAutoBaudChoices("38400", List.of("9600", "19200", "38400"));
        laserSetAbsoluteMaxRange(absoluteMaxRange());
        laserSetDefaultTcpPort(8102);
        laserSetDefaultPortType("serial");
        setMaxSecondsToKeepCumulative(DEFAULT_MAX_SECONDS_TO_KEEP_CUMULATIVE);
        setMaxDistToKeepCumulative(DEFAULT_MAX_DIST_TO_KEEP_LASER_CUMULATIVE);
        setMinDistBetweenCumulative(DEFAULT_MIN_DIST_BETWEEN_CUMULATIVE);
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
            super.setMaxRange(Math.min(robot.getParameters().laserMaxRange(), getAbsoluteMaxRange()));
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

    /**
     * Chooses the angle between readings by its value, as ARIA's older lasers set it.
     *
     * @param degrees 1 ({@code one}: 181 readings a scan) or 0.5 ({@code half}: 361)
     * @return false for another value (logged)
     */
    @Override
    public boolean setIncrement(double degrees) {
        if (degrees != 1 && degrees != 0.5) {
            ArLog.log(ArLog.Normal, "%s::setIncrement: Cannot set increment to %g: choose one (1°) or half (0.5°)",
                    getName(), degrees);
            return false;
        }
        return chooseIncrement(degrees == 1 ? "one" : "half");
    }

    @Override
    public boolean chooseIncrement(String choice) {
        boolean ok = super.chooseIncrement(choice);
        reconfigure();
        return ok;
    }

    /**
     * Switches the laser on: needs the laser attached to a robot that is connected.
     *
     * @return true if the request was sent; otherwise {@link #getConnectionError()} says why
     */
    @Override
    public synchronized boolean blockingConnect() {
        ArRobot robot = getRobot();
        if (robot == null) {
            return fail("the laser is attached to no robot: attach it with ArRobot.addRangeDevice (or addLaser) first");
        }
        if (!robot.isConnected()) {
            return fail("robot " + robot.getName() + " is not connected: connect the robot first");
        }
        laserSetAbsoluteMaxRange(absoluteMaxRange());
        robot.send(new Command.ConfigureLaser(true, getIncrement(), getMaxRange()));
        connected = true;
        connectionError = null;
        ArLog.log(getInfoLogLevel(), "%s: Connected to laser", getName());
        return true;
    }

    /** @return as {@link #blockingConnect()}: a simulated laser connects at once */
    @Override
    public boolean asyncConnect() {
        return blockingConnect();
    }

    private boolean fail(String reason) {
        connectionError = reason;
        ArLog.log(ArLog.Terse, "%s: could not connect: %s", getName(), reason);
        return false;
    }

    /**
     * Switches the laser off; scans stop from the next step's state.
     *
     * @return whether it was connected
     */
    @Override
    public synchronized boolean disconnect() {
        ArRobot robot = getRobot();
        boolean was = isConnected();
        if (connected && robot != null && robot.isConnected()) {
            robot.send(new Command.ConfigureLaser(false, getIncrement(), getMaxRange()));
        }
        connected = false;
        return was;
    }

    /** @return whether the laser was switched on and its robot is still connected */
    @Override
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
            getRobot().send(new Command.ConfigureLaser(true, getIncrement(), getMaxRange()));
        }
    }

    /** @return the latest scan's ranges, mm from the laser, from its right to its left; a copy */
    public int[] getRawScan() {
        return rawScan.clone();
    }

    /**
     * The most the LMS200 reports with the units and reflector bits chosen, as ARIA's
     * {@code ArLMS2xx::laserCheckParams} works it out: 8 m, four times that with 1 reflector bit and
     * twice with 2, in mm; ten times in cm; 150 m in 10 cm.
     */
    private double absoluteMaxRange() {
        double metres = switch (getReflectorBitsChoice()) {
            case "2ref" -> 16;
            case "3ref" -> 8;
            default -> 32;
        };
        return switch (getUnitsChoice()) {
            case "1cm" -> metres * 10_000;
            case "10cm" -> 150_000;
            default -> metres * 1000;
        };
    }

    /** @return mm a range is rounded to: the units chosen */
    private int unitMm() {
        return switch (getUnitsChoice()) {
            case "1cm" -> 10;
            case "10cm" -> 100;
            default -> 1;
        };
    }

    /**
     * Turns the robot's latest scan into raw readings; those below the maximum range, within the
     * field of view and not ignored become the current buffer, and the scan is taken into the
     * cumulative buffer by ARIA's laser rules.
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
        double mountX = hasSensorPosition() ? getSensorPositionX() : p.laserX();
        double mountY = hasSensorPosition() ? getSensorPositionY() : p.laserY();
        double mountTh = hasSensorPosition() ? getSensorPositionTh() : p.laserTh();
        ArPose pose = robotPose();
        // the step follows from the scan's length, so a scan taken before a change of increment
        // is still read right
        double step = scan.length > 1 ? 180.0 / (scan.length - 1) : 0;
        double max = getMaxRange();
        double half = getDegreesChoiceDouble() / 2;
        int unit = unitMm();
        boolean mirrored = getFlipped();
        List<ArSensorReading> readings = new ArrayList<>(scan.length);
        List<double[]> hits = new ArrayList<>(scan.length);
        for (int i = 0; i < scan.length; i++) {
            double beam = -90 + i * step;
            if (Math.abs(beam) > half + 1e-9) {
                continue;
            }
            int range = unit == 1 ? scan[i] : (int) Math.round(scan[i] / (double) unit) * unit;
            double angle = mirrored ? -beam : beam;
            ArSensorReading r = new ArSensorReading(mountX, mountY, mountTh + angle, (int) max);
            r.newData(range, pose, robot.getCounter(), s.timeMs());
            readings.add(r);
            if (range < max && !ignores(angle)) {
                hits.add(new double[] {r.getX(), r.getY()});
            }
        }
        rawScan = scan;
        setRawReadings(readings);
        if (scan.length > 0) {
            replaceCurrent(hits, pose, s.timeMs());
            cumulativeRules.take(cumulativeBuffer(), readings, max, getMaxInsertDistCumulative(),
                    getMinDistBetweenCumulative(), pose, s.timeMs());
        }
    }
}
