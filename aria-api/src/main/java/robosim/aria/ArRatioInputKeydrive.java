package robosim.aria;

/**
 * The arrow keys as ratios for an {@link ArActionRatioInput}, as ARIA's
 * {@code ArRatioInputKeydrive} (ArRatioInputKeydrive.cpp): each UP or DOWN press moves the
 * translation ratio by the velocity increment (ARIA's default 5, up to ±100), LEFT or RIGHT turns
 * full left or right for one firing, SPACE zeroes the ratios; the throttle is 100. It gives the
 * ratios from a fire callback of the input (ARIA's default priority 25) and takes the keys of the
 * program's key handler ({@link Aria#getKeyHandler()}) at the first firing; activating the input
 * zeroes its ratios and takes the keys again, deactivating gives them up.
 *
 * <p>ARIA's makes a terminal key handler at the first firing when the program has none; RoboSim's
 * does not (see {@link ArActionKeydrive}): without one, the keys are not read and {@link #up()} and
 * the others are the input.
 */
public class ArRatioInputKeydrive {
    private final ArRobot robot;
    private final ArActionRatioInput input;
    private final double velIncrement;
    private final Runnable upCB = this::up;
    private final Runnable downCB = this::down;
    private final Runnable leftCB = this::left;
    private final Runnable rightCB = this::right;
    private final Runnable spaceCB = this::space;
    private final Runnable fireCB = this::fireCallback;
    private boolean haveKeys;
    private double transRatio;
    private double rotRatio;
    private double throttle = 100;

    /**
     * @param robot the robot
     * @param input the ratio input it drives, at ARIA's priority 25 and increment 5
     */
    public ArRatioInputKeydrive(ArRobot robot, ArActionRatioInput input) {
        this(robot, input, 25);
    }

    /**
     * @param robot    the robot
     * @param input    the ratio input it drives
     * @param priority its fire callback's priority on the input
     */
    public ArRatioInputKeydrive(ArRobot robot, ArActionRatioInput input, int priority) {
        this(robot, input, priority, 5);
    }

    /**
     * @param robot        the robot
     * @param input        the ratio input it drives
     * @param priority     its fire callback's priority on the input
     * @param velIncrement the translation ratio step per UP or DOWN press
     */
    public ArRatioInputKeydrive(ArRobot robot, ArActionRatioInput input, int priority, double velIncrement) {
        this.robot = robot;
        this.input = input;
        this.velIncrement = velIncrement;
        input.addFireCallback(priority, fireCB);
        input.addActivateCallback(this::activate);
        input.addDeactivateCallback(this::deactivate);
    }

    /** UP: the translation ratio up by the increment, at most 100. */
    public synchronized void up() {
        transRatio = Math.min(100, transRatio + velIncrement);
    }

    /** DOWN: the translation ratio down by the increment, at least -100. */
    public synchronized void down() {
        transRatio = Math.max(-100, transRatio - velIncrement);
    }

    /** LEFT: full left, for the next firing. */
    public synchronized void left() {
        rotRatio = 100;
    }

    /** RIGHT: full right, for the next firing. */
    public synchronized void right() {
        rotRatio = -100;
    }

    /** SPACE: the ratios to 0. */
    public synchronized void space() {
        transRatio = 0;
        rotRatio = 0;
    }

    /** Takes UP, DOWN, LEFT, RIGHT and SPACE of the program's key handler, as ARIA's. */
    public void takeKeys() {
        synchronized (this) {
            haveKeys = true;
        }
        ArKeyHandler keys = Aria.getKeyHandler();
        if (keys == null) {
            ArLog.log(ArLog.Verbose, "ArRatioInputKeydrive::takeKeys: There is no key handler, keydrive will not work.");
            return;
        }
        take(keys, ArKeyHandler.UP, upCB, "up");
        take(keys, ArKeyHandler.DOWN, downCB, "down");
        take(keys, ArKeyHandler.LEFT, leftCB, "left");
        take(keys, ArKeyHandler.RIGHT, rightCB, "right");
        take(keys, ArKeyHandler.SPACE, spaceCB, "space");
    }

    private static void take(ArKeyHandler keys, int key, Runnable cb, String name) {
        if (!keys.addKeyHandler(key, cb)) {
            ArLog.log(ArLog.Terse, "The key handler already has a key for %s, keydrive will not work correctly.", name);
        }
    }

    /** Gives the keys back, as ARIA's {@code giveUpKeys}. */
    public void giveUpKeys() {
        synchronized (this) {
            haveKeys = false;
        }
        ArKeyHandler keys = Aria.getKeyHandler();
        if (keys == null) {
            return;
        }
        for (Runnable cb : new Runnable[] {upCB, downCB, leftCB, rightCB, spaceCB}) {
            keys.remKeyHandler(cb);
        }
    }

    /** @return whether it holds its keys */
    public synchronized boolean haveKeys() {
        return haveKeys;
    }

    private void activate() {
        boolean take;
        synchronized (this) {
            transRatio = 0;
            rotRatio = 0;
            take = haveKeys;
        }
        if (take) {
            takeKeys();
        }
    }

    private void deactivate() {
        if (haveKeys()) {
            giveUpKeys();
        }
    }

    private void fireCallback() {
        boolean take;
        synchronized (this) {
            input.setTransRatio(transRatio);
            input.setRotRatio(rotRatio);
            input.setLatRatio(0);
            input.setThrottleRatio(throttle);
            rotRatio = 0;
            take = !haveKeys;
        }
        if (take) {
            takeKeys();
        }
    }

    /** @return the robot it was made for */
    public ArRobot getRobot() {
        return robot;
    }
}
