package robosim.aria;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Logger;
import robosim.protocol.Command;
import robosim.protocol.RobotState;
import robosim.protocol.RobotParameters;

/**
 * A SICK LMS200 laser as a range device (ARIA 2.x's {@code ArSick}), named {@code laser}: it scans
 * 180°, from 90° right to 90° left of its mounting heading, at 1° (181 readings) or 0.5° (361)
 * steps, up to 8000 mm. Each cycle the robot's latest scan becomes the raw readings
 * ({@link #getRawReadings()}), and the readings below the maximum range (the ones that hit
 * something) go into the buffers. The mounting pose is the parameter file's
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

    /** Turns the robot's latest scan into raw readings and adds those below the maximum range. */
    @Override
    protected void processReadings() {
        ArRobot robot = getRobot();
        RobotState s = cycleState();
        if (robot == null || s == null) {
            return;
        }
        int[] scan = s.laser() == null ? new int[0] : s.laser().clone();
        RobotParameters p = robot.getParameters();
        ArPose pose = robotPose();
        // the step follows from the scan's length, so a scan taken before a change of increment
        // is still read right
        double step = scan.length > 1 ? 180.0 / (scan.length - 1) : 0;
        double max = getMaxRange();
        List<ArSensorReading> readings = new ArrayList<>(scan.length);
        for (int i = 0; i < scan.length; i++) {
            ArSensorReading r = new ArSensorReading(p.laserX(), p.laserY(), p.laserTh() - 90 + i * step, (int) max);
            r.newData(scan[i], pose, robot.getCounter(), s.timeMs());
            readings.add(r);
            if (scan[i] < max) {
                addReading(r.getX(), r.getY(), pose, s.timeMs());
            }
        }
        rawScan = scan;
        setRawReadings(readings);
    }
}
