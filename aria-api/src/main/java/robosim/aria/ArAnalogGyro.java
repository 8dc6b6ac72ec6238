package robosim.aria;

/**
 * A robot's analog gyro, as ARIA's {@code ArAnalogGyro} (ArAnalogGyro.h, ArAnalogGyro.cpp): programs
 * such as gotoActionExample.cpp make one for their robot so that, on a robot with a gyro, its
 * readings correct the odometry's heading.
 *
 * <p><b>In the simulator:</b> no simulated robot has a gyro (ARIA's parameter {@code HasGyro} and the
 * controller's gyro type are 0), so it takes ARIA's path for a robot without one
 * ({@code GYRO_NONE} in {@code ArAnalogGyro::stabilizingCallback}): it sends nothing, never has data,
 * and the robot's heading is the odometry's alone. The flags and settings answer as ARIA's do then.
 */
public class ArAnalogGyro {
    private final ArRobot robot;
    private boolean active = true;
    private double scalingFactor;
    private boolean logAnomalies;

    /**
     * @param robot the robot whose gyro it is
     * @throws IllegalArgumentException if {@code robot} is null
     */
    public ArAnalogGyro(ArRobot robot) {
        if (robot == null) {
            throw new IllegalArgumentException("null was supplied for robot: a gyro belongs to a robot");
        }
        this.robot = robot;
    }

    /** @return the robot given */
    public ArRobot getRobot() {
        return robot;
    }

    /** @return whether the gyro is used for the heading: true until {@link #deactivate()}, as in ARIA */
    public synchronized boolean isActive() {
        return active;
    }

    /** Uses the gyro for the heading again (ARIA's {@code activate}). */
    public synchronized void activate() {
        active = true;
    }

    /** Stops using the gyro for the heading (ARIA's {@code deactivate}). */
    public synchronized void deactivate() {
        active = false;
    }

    /** @return false: only a controller's gyro has a gyro-only mode, and the simulated robots have none */
    public boolean hasGyroOnlyMode() {
        return false;
    }

    /** @return false: without a gyro-only mode it is never active */
    public boolean isGyroOnlyActive() {
        return false;
    }

    /** ARIA's {@code activateGyroOnly}: without a gyro-only mode it does nothing, as ARIA's. */
    public void activateGyroOnly() {
        // ARIA: only a GYRO_ANALOG_CONTROLLER has the mode to switch to
    }

    /** @return true: the gyro gives this class no data of its own (ARIA's {@code hasNoInternalData}) */
    public boolean hasNoInternalData() {
        return true;
    }

    /** @return false: no gyro packet ever arrives */
    public boolean haveGottenData() {
        return false;
    }

    /** @return false, as {@link #haveGottenData()} */
    public boolean haveData() {
        return false;
    }

    /** @return the gyro's heading, degrees: 0, as ARIA's before any reading */
    public double getHeading() {
        return 0;
    }

    /** @return the gyro's temperature: 0, as ARIA's before any reading */
    public int getTemperature() {
        return 0;
    }

    /** @return the gyro packets in the last second: 0 */
    public int getPacCount() {
        return 0;
    }

    /** @return the gyro's resting average: 0, as ARIA's before one is taken */
    public double getAverage() {
        return 0;
    }

    /** @return the scaling factor (ARIA's {@code GyroScaler}; 0 until set) */
    public synchronized double getScalingFactor() {
        return scalingFactor;
    }

    /** @param factor the scaling factor to keep */
    public synchronized void setScalingFactor(double factor) {
        scalingFactor = factor;
    }

    /** @return whether anomalies would be logged */
    public synchronized boolean getLogAnomalies() {
        return logAnomalies;
    }

    /** @param logAnomalies whether anomalies in the gyro's readings would be logged */
    public synchronized void setLogAnomalies(boolean logAnomalies) {
        this.logAnomalies = logAnomalies;
    }

    /**
     * ARIA's Kalman filter model of the gyro; kept for the calls' sake, with no readings to filter.
     *
     * @param gyroSigma   the gyro's noise, degrees
     * @param inertialVar the inertial variance
     * @param rotVar      the rotational variance, deg²/deg
     * @param transVar    the translational variance, deg²/m
     */
    public void setFilterModel(double gyroSigma, double inertialVar, double rotVar, double transVar) {
        // no readings: nothing to filter
    }
}
