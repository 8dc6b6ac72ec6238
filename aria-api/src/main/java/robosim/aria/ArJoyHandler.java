package robosim.aria;

/**
 * The computer's joystick, as ARIA's {@code ArJoyHandler} (ArJoyHandler.h, ArJoyHandler_LIN.cpp),
 * in a simulator that has none: {@link #init()} finds no joystick and returns false,
 * {@link #haveJoystick()} stays false, no button is pressed, and the stick reads centred (0 on each
 * axis). This is what ARIA's handler reports on a computer without {@code /dev/input/js0}, so the
 * actions that read a joystick ({@link ArActionJoydrive}, {@code ArRatioInputJoydrive}) behave as
 * ARIA's do there: they want nothing.
 *
 * <p>The calibration calls (start, end, stats) and the speeds keep their values as ARIA's do; with
 * no joystick the readings they would scale are all 0. C++'s output pointers are arrays here: each
 * call fills element 0 of each non-null array it is given.
 */
public class ArJoyHandler {
    private boolean useOSCal;
    private final boolean useOld;
    private boolean initialized;
    private int maxX, minX, maxY, minY, cenX, cenY;
    private int topX = 1, topY = 1, topZ = 1;

    /** A handler using the operating system's calibration (ARIA's defaults). */
    public ArJoyHandler() {
        this(true, false);
    }

    /** @param useOSCal whether the operating system's calibration is used (else its own) */
    public ArJoyHandler(boolean useOSCal) {
        this(useOSCal, false);
    }

    /**
     * @param useOSCal       whether the operating system's calibration is used (else its own)
     * @param useOldJoystick whether ARIA's old Linux joystick interface is used (no difference here)
     */
    public ArJoyHandler(boolean useOSCal, boolean useOldJoystick) {
        this.useOSCal = useOSCal;
        this.useOld = useOldJoystick;
    }

    /**
     * Looks for the joystick, as ARIA's {@code init}: the simulator has none.
     *
     * @return false: no joystick was found
     */
    public synchronized boolean init() {
        initialized = false;
        ArLog.log(ArLog.Verbose, "ArJoyHandler: no joystick in the simulation%s", useOld ? " (old interface)" : "");
        return initialized;
    }

    /** @return whether a joystick was found by {@link #init()}: never in the simulation */
    public synchronized boolean haveJoystick() {
        return initialized;
    }

    /** @return whether the joystick has a throttle (Z) axis: no joystick, none */
    public boolean haveZAxis() {
        return false;
    }

    /**
     * The stick's position, each axis from -1 to 1: 0 without a joystick.
     *
     * @param x its X (left-right), or null
     * @param y its Y (forward-back), or null
     */
    public void getDoubles(double[] x, double[] y) {
        getDoubles(x, y, null);
    }

    /**
     * @param x its X, or null
     * @param y its Y, or null
     * @param z its throttle, or null
     */
    public void getDoubles(double[] x, double[] y, double[] z) {
        put(x, 0.0);
        put(y, 0.0);
        put(z, 0.0);
    }

    /**
     * @param button a button's number, from 1
     * @return whether it is pressed: no joystick, never
     */
    public boolean getButton(int button) {
        return false;
    }

    /**
     * The maximums {@link #getAdjusted} scales to, as ARIA's {@code setSpeeds}.
     *
     * @param x the X axis's
     * @param y the Y axis's
     */
    public void setSpeeds(int x, int y) {
        setSpeeds(x, y, 0);
    }

    /**
     * @param x the X axis's
     * @param y the Y axis's
     * @param z the throttle's
     */
    public synchronized void setSpeeds(int x, int y, int z) {
        topX = x;
        topY = y;
        topZ = z;
    }

    /**
     * @param x the X maximum, or null
     * @param y the Y maximum, or null
     * @param z the throttle's maximum, or null
     */
    public synchronized void getSpeeds(int[] x, int[] y, int[] z) {
        put(x, topX);
        put(y, topY);
        put(z, topZ);
    }

    /**
     * The stick's position scaled to the speeds: 0 without a joystick.
     *
     * @param x its X, or null
     * @param y its Y, or null
     */
    public void getAdjusted(int[] x, int[] y) {
        getAdjusted(x, y, null);
    }

    /**
     * @param x its X, or null
     * @param y its Y, or null
     * @param z its throttle, or null
     */
    public void getAdjusted(int[] x, int[] y, int[] z) {
        put(x, 0);
        put(y, 0);
        put(z, 0);
    }

    /**
     * The raw readings: 0 without a joystick.
     *
     * @param x its X, or null
     * @param y its Y, or null
     */
    public void getUnfiltered(int[] x, int[] y) {
        getUnfiltered(x, y, null);
    }

    /**
     * @param x its X, or null
     * @param y its Y, or null
     * @param z its throttle, or null
     */
    public void getUnfiltered(int[] x, int[] y, int[] z) {
        put(x, 0);
        put(y, 0);
        put(z, 0);
    }

    /** @return how many axes the joystick has: none */
    public int getNumAxes() {
        return 0;
    }

    /**
     * @param axis an axis's number, from 1
     * @return its position from -1 to 1: 0 without a joystick
     */
    public double getAxis(int axis) {
        return 0;
    }

    /** @return how many buttons the joystick has: none */
    public int getNumButtons() {
        return 0;
    }

    /** @param useOSCal whether the operating system's calibration is used */
    public synchronized void setUseOSCal(boolean useOSCal) {
        this.useOSCal = useOSCal;
    }

    /** @return whether the operating system's calibration is used */
    public synchronized boolean getUseOSCal() {
        return useOSCal;
    }

    /** Starts calibrating, as ARIA's: minimum, maximum and centre at the raw reading (0 here). */
    public synchronized void startCal() {
        maxX = minX = maxY = minY = cenX = cenY = 0;
    }

    /** Ends calibrating, as ARIA's: the centre where the stick is now (0 here). */
    public synchronized void endCal() {
        cenX = 0;
        cenY = 0;
    }

    /**
     * The calibration, as ARIA's {@code getStats}.
     *
     * @param maxX X's maximum, or null
     * @param minX X's minimum, or null
     * @param maxY Y's maximum, or null
     * @param minY Y's minimum, or null
     * @param cenX X's centre, or null
     * @param cenY Y's centre, or null
     */
    public synchronized void getStats(int[] maxX, int[] minX, int[] maxY, int[] minY, int[] cenX, int[] cenY) {
        put(maxX, this.maxX);
        put(minX, this.minX);
        put(maxY, this.maxY);
        put(minY, this.minY);
        put(cenX, this.cenX);
        put(cenY, this.cenY);
    }

    /**
     * Restores a calibration, as ARIA's {@code setStats}.
     *
     * @param maxX X's maximum
     * @param minX X's minimum
     * @param maxY Y's maximum
     * @param minY Y's minimum
     * @param cenX X's centre
     * @param cenY Y's centre
     */
    public synchronized void setStats(int maxX, int minX, int maxY, int minY, int cenX, int cenY) {
        this.maxX = maxX;
        this.minX = minX;
        this.maxY = maxY;
        this.minY = minY;
        this.cenX = cenX;
        this.cenY = cenY;
    }

    private static void put(double[] out, double value) {
        if (out != null && out.length > 0) {
            out[0] = value;
        }
    }

    private static void put(int[] out, int value) {
        if (out != null && out.length > 0) {
            out[0] = value;
        }
    }
}
