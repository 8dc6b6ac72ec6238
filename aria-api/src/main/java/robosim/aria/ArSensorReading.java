package robosim.aria;

/**
 * One range sensor's latest reading, as ARIA keeps it: the range, where the echo lies (globally and
 * in the robot's frame), the sensor's mounting pose, and when the reading was taken (the robot's
 * pose and cycle counter).
 */
public final class ArSensorReading {
    private double sensorX;
    private double sensorY;
    private double sensorTh;
    /** The cosine and sine of the sensor's heading, worked out once when it is mounted, not at every reading. */
    private double sensorCos;
    private double sensorSin;
    private int range;
    private double x;
    private double y;
    private double localX;
    private double localY;
    private ArPose poseTaken = new ArPose();
    private long counterTaken;
    private long timeTaken;
    private boolean ignoreThisReading = true;

    /**
     * A sensor that has not reported yet: its range reads {@code initialRange} and
     * {@link #getIgnoreThisReading()} is true.
     *
     * @param sensorX      mounting x, mm forward of the robot centre
     * @param sensorY      mounting y, mm left of the robot centre
     * @param sensorTh     mounting heading, degrees
     * @param initialRange the range reported before any data, mm (ARIA: 5000 for a sonar)
     */
    public ArSensorReading(double sensorX, double sensorY, double sensorTh, int initialRange) {
        resetSensorPosition(sensorX, sensorY, sensorTh);
        this.range = initialRange;
    }

    /**
     * Moves the sensor on the robot.
     *
     * @param sensorX  mm
     * @param sensorY  mm
     * @param sensorTh degrees
     */
    public void resetSensorPosition(double sensorX, double sensorY, double sensorTh) {
        this.sensorX = sensorX;
        this.sensorY = sensorY;
        this.sensorTh = ArMath.fixAngle(sensorTh);
        double th = Math.toRadians(this.sensorTh);
        this.sensorCos = Math.cos(th);
        this.sensorSin = Math.sin(th);
    }

    /**
     * Takes a new reading.
     *
     * @param range     mm from the sensor
     * @param robotPose the robot's pose when it was taken
     * @param counter   the robot's cycle counter when it was taken
     * @param timeMs    simulated time when it was taken
     */
    public void newData(int range, ArPose robotPose, long counter, long timeMs) {
        this.range = range;
        localX = sensorX + range * sensorCos;
        localY = sensorY + range * sensorSin;
        double rth = Math.toRadians(robotPose.getTh());
        double cos = Math.cos(rth);
        double sin = Math.sin(rth);
        x = robotPose.getX() + localX * cos - localY * sin;
        y = robotPose.getY() + localX * sin + localY * cos;
        poseTaken = new ArPose(robotPose.getX(), robotPose.getY(), robotPose.getTh());
        counterTaken = counter;
        timeTaken = timeMs;
        ignoreThisReading = false;
    }

    /** @return a copy of this reading, so that a device's raw readings do not move with the robot's */
    ArSensorReading copy() {
        ArSensorReading c = new ArSensorReading(sensorX, sensorY, sensorTh, range);
        c.x = x;
        c.y = y;
        c.localX = localX;
        c.localY = localY;
        c.poseTaken = new ArPose(poseTaken.getX(), poseTaken.getY(), poseTaken.getTh());
        c.counterTaken = counterTaken;
        c.timeTaken = timeTaken;
        c.ignoreThisReading = ignoreThisReading;
        return c;
    }

    /**
     * Moves the reading's global position and the pose it was taken at by a rigid motion, as ARIA's
     * {@code ArSensorReading::applyTransform} does when the robot is moved ({@link ArRobot#moveTo}).
     *
     * @param t the motion
     */
    void applyTransform(ArTransform t) {
        double nx = t.transformX(x, y);
        y = t.transformY(x, y);
        x = nx;
        poseTaken = t.doTransform(poseTaken);
    }

    /** @return the range from the sensor, mm */
    public int getRange() {
        return range;
    }

    /** @return the echo's global x, mm */
    public double getX() {
        return x;
    }

    /** @return the echo's global y, mm */
    public double getY() {
        return y;
    }

    /** @return the echo's position in the world, heading 0 */
    public ArPose getPose() {
        return new ArPose(x, y, 0);
    }

    /** @return the echo's x in the robot frame when taken, mm */
    public double getLocalX() {
        return localX;
    }

    /** @return the echo's y in the robot frame when taken, mm */
    public double getLocalY() {
        return localY;
    }

    /** @return the sensor's mounting x, mm */
    public double getSensorX() {
        return sensorX;
    }

    /** @return the sensor's mounting y, mm */
    public double getSensorY() {
        return sensorY;
    }

    /** @return the sensor's mounting heading, degrees */
    public double getSensorTh() {
        return sensorTh;
    }

    /** @return the sensor's mounting pose on the robot */
    public ArPose getSensorPosition() {
        return new ArPose(sensorX, sensorY, sensorTh);
    }

    /** @return the robot's pose when the reading was taken */
    public ArPose getPoseTaken() {
        return new ArPose(poseTaken.getX(), poseTaken.getY(), poseTaken.getTh());
    }

    /** @return the robot's cycle counter when the reading was taken */
    public long getCounterTaken() {
        return counterTaken;
    }

    /** @return simulated time when the reading was taken, ms */
    public long getTimeTaken() {
        return timeTaken;
    }

    /**
     * @param counter the robot's current cycle counter
     * @return whether the reading was taken in that cycle
     */
    public boolean isNew(long counter) {
        return counter == counterTaken;
    }

    /** @return true until the first data arrives */
    public boolean getIgnoreThisReading() {
        return ignoreThisReading;
    }
}
