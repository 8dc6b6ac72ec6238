package robosim.aria;

/**
 * One range sensor's latest reading, as ARIA keeps it ({@code ArSensorReading}, ArSensorReading.h
 * and ArSensorReading.cpp): the range, where the echo lies (globally and in the robot's frame), the
 * sensor's mounting pose, and when the reading was taken (the robot's pose and cycle counter).
 *
 * <p>It takes data in three forms: ARIA's two {@code newData} forms (a range, or the echo's position
 * relative to the sensor, with the robot's pose, encoder pose, a transform to global coordinates,
 * the counter and an {@link ArTime}); RoboSim's own, which the sonar ring and the laser use (a range,
 * the robot's pose, the counter, the simulated time in ms); and the original RoboSim's
 * {@link #newData(int, double, double, long)} (a range, the echo's global position, the counter).
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
    private ArPose encoderPoseTaken = new ArPose();
    private long counterTaken;
    private long timeTaken;
    private boolean ignoreThisReading = true;
    private int extraInt;
    private boolean adjusted;

    /** ARIA's default constructor: a sensor at the robot's centre, facing forward (see {@link #ArSensorReading(double, double, double)}). */
    public ArSensorReading() {
        this(0, 0, 0);
    }

    /**
     * ARIA's constructor ({@code ArSensorReading(xPos, yPos, thPos)}, ArSensorReading.cpp), with
     * ARIA's starting values: range 5000, the echo at (-1, -1), taken at pose (-1, -1, -1), counter
     * 0, not to be ignored.
     *
     * @param xPos  mounting x, mm forward of the robot centre
     * @param yPos  mounting y, mm left of the robot centre
     * @param thPos mounting heading, degrees
     */
    public ArSensorReading(double xPos, double yPos, double thPos) {
        this(xPos, yPos, thPos, 5000);
        x = -1;
        y = -1;
        poseTaken = new ArPose(-1, -1, -1);
        ignoreThisReading = false;
    }

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
     * As ARIA's {@code resetSensorPosition(x, y, th, forceComputation)}: without
     * {@code forceComputation}, a position equal to the present one (the heading within 0.00001°)
     * changes nothing; a reading already taken keeps its positions either way.
     *
     * @param sensorX          mm
     * @param sensorY          mm
     * @param sensorTh         degrees
     * @param forceComputation whether to recompute even for the same position
     */
    public void resetSensorPosition(double sensorX, double sensorY, double sensorTh, boolean forceComputation) {
        if (!forceComputation && Math.abs(sensorTh - this.sensorTh) < .00001
                && sensorX == this.sensorX && sensorY == this.sensorY) {
            return;
        }
        resetSensorPosition(sensorX, sensorY, sensorTh);
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
     * ARIA's {@code newData(range, robotPose, encoderPose, trans, counter, timeTaken,
     * ignoreThisReading, extraInt)} (ArSensorReading.cpp): the echo lies {@code range} mm along the
     * sensor's heading from its mounting point, in the robot's frame ({@link #getLocalPose()}), and
     * {@code trans} carries that into global coordinates ({@link #getPose()}); pass the robot's
     * to-global transform, {@code new ArTransform(new ArPose(), robotPose)}. {@link #getAdjusted()}
     * turns false.
     *
     * @param range             mm from the sensor, 0 or more
     * @param robotPose         the robot's pose when it was taken
     * @param encoderPose       the robot's encoder pose when it was taken
     * @param trans             robot frame to global coordinates
     * @param counter           the robot's cycle counter when it was taken
     * @param timeTaken         when it was taken (its simulated ms are kept)
     * @param ignoreThisReading whether users should ignore it
     * @param extraInt          the device's extra value ({@link #getExtraInt()})
     * @throws IllegalArgumentException for a negative range (ARIA's is unsigned)
     */
    public void newData(int range, ArPose robotPose, ArPose encoderPose, ArTransform trans, long counter,
            ArTime timeTaken, boolean ignoreThisReading, int extraInt) {
        if (range < 0) {
            throw new IllegalArgumentException(range + " was supplied for range: a range is 0 or more");
        }
        this.range = range;
        setData(sensorX + range * sensorCos, sensorY + range * sensorSin, robotPose, encoderPose, trans, counter,
                timeTaken, ignoreThisReading, extraInt);
    }

    /**
     * ARIA's {@code newData(range, robotPose, encoderPose, trans, counter, timeTaken)}, with ARIA's
     * defaults: not to be ignored, extra value 0.
     *
     * @param range       mm from the sensor
     * @param robotPose   the robot's pose when it was taken
     * @param encoderPose the robot's encoder pose when it was taken
     * @param trans       robot frame to global coordinates
     * @param counter     the robot's cycle counter
     * @param timeTaken   when it was taken
     */
    public void newData(int range, ArPose robotPose, ArPose encoderPose, ArTransform trans, long counter,
            ArTime timeTaken) {
        newData(range, robotPose, encoderPose, trans, counter, timeTaken, false, 0);
    }

    /**
     * ARIA's {@code newData(sx, sy, robotPose, encoderPose, trans, counter, timeTaken,
     * ignoreThisReading, extraInt)}: the echo given relative to the sensor's mounting point, in the
     * robot's axes; the range is {@code sqrt(sx² + sy²)} truncated to whole mm, as ARIA's cast does.
     *
     * @param sx                the echo's x from the sensor, mm, robot axes
     * @param sy                the echo's y from the sensor, mm, robot axes
     * @param robotPose         the robot's pose when it was taken
     * @param encoderPose       the robot's encoder pose when it was taken
     * @param trans             robot frame to global coordinates
     * @param counter           the robot's cycle counter
     * @param timeTaken         when it was taken
     * @param ignoreThisReading whether users should ignore it
     * @param extraInt          the device's extra value
     */
    public void newData(int sx, int sy, ArPose robotPose, ArPose encoderPose, ArTransform trans, long counter,
            ArTime timeTaken, boolean ignoreThisReading, int extraInt) {
        this.range = (int) Math.sqrt((double) sx * sx + (double) sy * sy);
        setData(sensorX + sx, sensorY + sy, robotPose, encoderPose, trans, counter, timeTaken, ignoreThisReading,
                extraInt);
    }

    /**
     * ARIA's {@code newData(sx, sy, robotPose, encoderPose, trans, counter, timeTaken)}, with ARIA's
     * defaults: not to be ignored, extra value 0.
     *
     * @param sx          the echo's x from the sensor, mm
     * @param sy          the echo's y from the sensor, mm
     * @param robotPose   the robot's pose when it was taken
     * @param encoderPose the robot's encoder pose when it was taken
     * @param trans       robot frame to global coordinates
     * @param counter     the robot's cycle counter
     * @param timeTaken   when it was taken
     */
    public void newData(int sx, int sy, ArPose robotPose, ArPose encoderPose, ArTransform trans, long counter,
            ArTime timeTaken) {
        newData(sx, sy, robotPose, encoderPose, trans, counter, timeTaken, false, 0);
    }

    private void setData(double lx, double ly, ArPose robotPose, ArPose encoderPose, ArTransform trans, long counter,
            ArTime timeTaken, boolean ignore, int extra) {
        localX = lx;
        localY = ly;
        x = trans.transformX(lx, ly);
        y = trans.transformY(lx, ly);
        poseTaken = new ArPose(robotPose);
        encoderPoseTaken = new ArPose(encoderPose);
        counterTaken = counter;
        this.timeTaken = timeTaken.getTimeMs();
        ignoreThisReading = ignore;
        extraInt = extra;
        adjusted = false;
    }

    /**
     * The original RoboSim's {@code newData(int range, double x, double y, long counter)}: a reading
     * given by its range and the echo's global position, with the robot's cycle counter. The echo's
     * position in the robot's frame follows from the sensor's mounting pose and the range, as in
     * ARIA's form; the pose and time it was taken at are not given, so they stay as they were. The
     * reading is then not to be ignored.
     *
     * @param range   mm from the sensor
     * @param x       the echo's global x, mm
     * @param y       the echo's global y, mm
     * @param counter the robot's cycle counter when it was taken
     */
    public void newData(int range, double x, double y, long counter) {
        this.range = range;
        this.localX = sensorX + range * sensorCos;
        this.localY = sensorY + range * sensorSin;
        this.x = x;
        this.y = y;
        this.counterTaken = counter;
        this.ignoreThisReading = false;
        this.adjusted = false;
    }

    /**
     * Takes a new reading (RoboSim's form, which the sonar ring and the laser use): the pose given
     * is also the encoder pose taken, and the reading is not to be ignored.
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
        encoderPoseTaken = new ArPose(poseTaken);
        counterTaken = counter;
        timeTaken = timeMs;
        ignoreThisReading = false;
        extraInt = 0;
        adjusted = false;
    }

    /** @return a copy of this reading, so that a device's raw readings do not move with the robot's */
    ArSensorReading copy() {
        ArSensorReading c = new ArSensorReading(sensorX, sensorY, sensorTh, range);
        c.x = x;
        c.y = y;
        c.localX = localX;
        c.localY = localY;
        c.poseTaken = new ArPose(poseTaken.getX(), poseTaken.getY(), poseTaken.getTh());
        c.encoderPoseTaken = new ArPose(encoderPoseTaken);
        c.extraInt = extraInt;
        c.adjusted = adjusted;
        c.counterTaken = counterTaken;
        c.timeTaken = timeTaken;
        c.ignoreThisReading = ignoreThisReading;
        return c;
    }

    /**
     * Moves the reading's global position and the pose it was taken at by a rigid motion, as ARIA's
     * {@code ArSensorReading::applyTransform} does when the robot is moved ({@link ArRobot#moveTo});
     * the position in the robot's frame and the encoder pose taken stay.
     *
     * @param t the motion
     */
    public void applyTransform(ArTransform t) {
        double nx = t.transformX(x, y);
        y = t.transformY(x, y);
        x = nx;
        poseTaken = t.doTransform(poseTaken);
    }

    /**
     * As ARIA's {@code applyEncoderTransform}: moves the encoder pose the reading was taken at.
     *
     * @param t the motion
     */
    public void applyEncoderTransform(ArTransform t) {
        encoderPoseTaken = t.doTransform(encoderPoseTaken);
    }

    /** @return whether a correction for the robot's motion was applied (ARIA's {@code getAdjusted}); false after new data */
    public boolean getAdjusted() {
        return adjusted;
    }

    /** @param adjusted whether a correction for the robot's motion was applied (ARIA's {@code setAdjusted}) */
    public void setAdjusted(boolean adjusted) {
        this.adjusted = adjusted;
    }

    /** @param ignoreThisReading whether users should ignore this reading (ARIA's {@code setIgnoreThisReading}) */
    public void setIgnoreThisReading(boolean ignoreThisReading) {
        this.ignoreThisReading = ignoreThisReading;
    }

    /**
     * ARIA's {@code getExtraInt}: a device's extra value with the reading (a laser's reflectance, 0 to
     * 255); 0 when the device gives none, as RoboSim's sonar and laser do.
     *
     * @return the extra value
     */
    public int getExtraInt() {
        return extraInt;
    }

    /** @param extraInt the device's extra value (ARIA's {@code setExtraInt}) */
    public void setExtraInt(int extraInt) {
        this.extraInt = extraInt;
    }

    /** @return the echo's position in the robot's frame when taken, heading 0 (ARIA's {@code getLocalPose}) */
    public ArPose getLocalPose() {
        return new ArPose(localX, localY, 0);
    }

    /**
     * @return the robot's encoder pose when the reading was taken (ARIA's {@code getEncoderPoseTaken});
     *         RoboSim's own {@code newData} takes the robot's pose for it
     */
    public ArPose getEncoderPoseTaken() {
        return new ArPose(encoderPoseTaken);
    }

    /** @return the cosine of the sensor's heading (ARIA's {@code getSensorDX}) */
    public double getSensorDX() {
        return sensorCos;
    }

    /** @return the sine of the sensor's heading (ARIA's {@code getSensorDY}) */
    public double getSensorDY() {
        return sensorSin;
    }

    /** @return the robot's x when the reading was taken, mm (ARIA's {@code getXTaken}) */
    public double getXTaken() {
        return poseTaken.getX();
    }

    /** @return the robot's y when the reading was taken, mm (ARIA's {@code getYTaken}) */
    public double getYTaken() {
        return poseTaken.getY();
    }

    /** @return the robot's heading when the reading was taken, degrees (ARIA's {@code getThTaken}) */
    public double getThTaken() {
        return poseTaken.getTh();
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

    /**
     * @return whether users should ignore the reading: for a reading made with RoboSim's constructor
     *         (the sonar ring's and laser's), true until the first data arrives; for one made with
     *         ARIA's, false from the start, as in ARIA; afterwards what the latest data said
     */
    public boolean getIgnoreThisReading() {
        return ignoreThisReading;
    }
}
