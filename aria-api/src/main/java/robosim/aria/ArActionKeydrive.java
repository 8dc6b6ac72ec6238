package robosim.aria;

/**
 * Drives from the arrow keys, as ARIA's {@code ArActionKeydrive} (ArActionKeydrive.cpp): the
 * program's key handler ({@link Aria#getKeyHandler()}) calls {@link #up()}, {@link #down()},
 * {@link #left()}, {@link #right()} and {@link #space()} on each press of UP, DOWN, LEFT, RIGHT and
 * SPACE. As ARIA's, it takes those keys when it is added to a robot and when it is activated, and
 * gives them up when it is deactivated (so {@link ArActionGroup#activateExclusive()} of another
 * group frees them); a key another handler holds is logged and left to it.
 *
 * <p>ARIA's makes a terminal key handler (and attaches it to the robot) when the program has none;
 * RoboSim's does not, since a program may feed the keys itself: the RemoteControl's window (with
 * {@code --keydrive}) calls the five methods directly, from any thread. A program that wants ARIA's
 * behaviour makes its {@link ArKeyHandler}, sets it with {@link Aria#setKeyHandler} and attaches it
 * with {@link ArRobot#attachKeyHandler}, as ARIA's examples do, before adding the action.
 *
 * <p>Each up or down press raises or lowers the speed by the velocity increment, up to the maximum
 * either way; each left or right press adds the turn increment to the delta heading of the next
 * cycle, up to the maximum turn amount, and that turn is asked for once. Space stops: speed and
 * turn back to 0. The speed it asks for is held within what the actions of higher priority allow
 * (their maximum velocities), and when they took all of the velocity's strength it starts again
 * from the robot's own velocity.
 */
public class ArActionKeydrive extends ArAction {
    /** ARIA's default top speed, mm/s. */
    public static final double DEFAULT_TRANS_VEL_MAX = 400;
    /** ARIA's default largest turn in one cycle, degrees. */
    public static final double DEFAULT_TURN_AMOUNT_MAX = 24;
    /** ARIA's default speed step per up or down press, mm/s. */
    public static final double DEFAULT_VEL_INCREMENT = 25;
    /** ARIA's default turn step per left or right press, degrees. */
    public static final double DEFAULT_TURN_INCREMENT = 8;

    private final ArActionDesired desired = new ArActionDesired();
    private double transVelMax;
    private double turnAmountMax;
    private double velIncrement;
    private double turnIncrement;
    private double deltaVel;
    private double turnAmount;
    private double desiredSpeed;
    private boolean speedReset = true;
    private final Runnable upCB = this::up;
    private final Runnable downCB = this::down;
    private final Runnable leftCB = this::left;
    private final Runnable rightCB = this::right;
    private final Runnable spaceCB = this::space;

    /** A keydrive named {@code keydrive} with ARIA's speeds and increments. */
    public ArActionKeydrive() {
        this("keydrive", DEFAULT_TRANS_VEL_MAX, DEFAULT_TURN_AMOUNT_MAX, DEFAULT_VEL_INCREMENT, DEFAULT_TURN_INCREMENT);
    }

    /** @param name the action's name; ARIA's speeds and increments */
    public ArActionKeydrive(String name) {
        this(name, DEFAULT_TRANS_VEL_MAX, DEFAULT_TURN_AMOUNT_MAX, DEFAULT_VEL_INCREMENT, DEFAULT_TURN_INCREMENT);
    }

    /**
     * @param name          the action's name
     * @param transVelMax   the top speed either way, mm/s
     * @param turnAmountMax the largest turn in one cycle, degrees
     * @param velIncrement  the speed step per up or down press, mm/s
     * @param turnIncrement the turn step per left or right press, degrees
     */
    public ArActionKeydrive(String name, double transVelMax, double turnAmountMax, double velIncrement,
            double turnIncrement) {
        super(name, "This action reads the keyboard arrow keys and sets the translational and rotational"
                + " velocities based on this.");
        setSpeeds(transVelMax, turnAmountMax);
        setIncrements(velIncrement, turnIncrement);
        setNextArgument(ArArg.ofDouble("trans vel max", () -> this.transVelMax, v -> this.transVelMax = v,
                "The maximum speed to go (mm/sec)"));
        setNextArgument(ArArg.ofDouble("turn amount max", () -> this.turnAmountMax, v -> this.turnAmountMax = v,
                "The maximum amount to turn (deg/cycle)"));
        setNextArgument(ArArg.ofDouble("vel increment per keypress", () -> this.velIncrement,
                v -> this.velIncrement = v, "The amount to increment velocity by per keypress (mm/sec)"));
        setNextArgument(ArArg.ofDouble("turn increment per keypress", () -> this.turnIncrement,
                v -> this.turnIncrement = v, "The amount to turn by per keypress (deg)"));
    }

    /**
     * @param name        the action's name
     * @param transVelMax the top speed either way, mm/s; ARIA's other defaults
     */
    public ArActionKeydrive(String name, double transVelMax) {
        this(name, transVelMax, DEFAULT_TURN_AMOUNT_MAX, DEFAULT_VEL_INCREMENT, DEFAULT_TURN_INCREMENT);
    }

    /**
     * @param name          the action's name
     * @param transVelMax   the top speed either way, mm/s
     * @param turnAmountMax the largest turn in one cycle, degrees; ARIA's increments
     */
    public ArActionKeydrive(String name, double transVelMax, double turnAmountMax) {
        this(name, transVelMax, turnAmountMax, DEFAULT_VEL_INCREMENT, DEFAULT_TURN_INCREMENT);
    }

    /**
     * @param name          the action's name
     * @param transVelMax   the top speed either way, mm/s
     * @param turnAmountMax the largest turn in one cycle, degrees
     * @param velIncrement  the speed step per up or down press, mm/s; ARIA's turn increment
     */
    public ArActionKeydrive(String name, double transVelMax, double turnAmountMax, double velIncrement) {
        this(name, transVelMax, turnAmountMax, velIncrement, DEFAULT_TURN_INCREMENT);
    }

    /**
     * As ARIA's: takes the keys of the program's key handler, if it has one.
     *
     * @param robot the robot, or null when removed
     */
    @Override
    public void setRobot(ArRobot robot) {
        super.setRobot(robot);
        if (robot != null) {
            takeKeys();
        }
    }

    /**
     * Adds UP, DOWN, LEFT, RIGHT and SPACE to the program's key handler ({@link Aria#getKeyHandler()}),
     * as ARIA's {@code takeKeys}; a key it already has is logged and left as it is. Without a key
     * handler, nothing (logged).
     */
    public void takeKeys() {
        ArKeyHandler keys = Aria.getKeyHandler();
        if (keys == null) {
            ArLog.log(ArLog.Verbose, "ArActionKeydrive::takeKeys: There is no key handler; %s is driven by its"
                    + " methods only.", getName());
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

    /** Removes its keys from the program's key handler, as ARIA's {@code giveUpKeys}. */
    public void giveUpKeys() {
        ArKeyHandler keys = Aria.getKeyHandler();
        if (keys == null) {
            return;
        }
        giveUp(keys, upCB, "up");
        giveUp(keys, downCB, "down");
        giveUp(keys, leftCB, "left");
        giveUp(keys, rightCB, "right");
        giveUp(keys, spaceCB, "space");
    }

    private static void giveUp(ArKeyHandler keys, Runnable cb, String name) {
        if (!keys.remKeyHandler(cb)) {
            ArLog.log(ArLog.Terse, "ArActionKeydrive: The key handler already didn't have a key for %s, something is"
                    + " wrong.", name);
        }
    }

    /** As ARIA's: an inactive keydrive takes its keys again when activated. */
    @Override
    public synchronized void activate() {
        if (!isActive()) {
            takeKeys();
        }
        super.activate();
    }

    /**
     * @param transVelMax   the top speed either way, mm/s
     * @param turnAmountMax the largest turn in one cycle, degrees
     */
    public synchronized void setSpeeds(double transVelMax, double turnAmountMax) {
        this.transVelMax = ActionArgs.nonNegative(getName(), "transVelMax", transVelMax);
        this.turnAmountMax = ActionArgs.nonNegative(getName(), "turnAmountMax", turnAmountMax);
    }

    /**
     * @param velIncrement  the speed step per up or down press, mm/s
     * @param turnIncrement the turn step per left or right press, degrees
     */
    public synchronized void setIncrements(double velIncrement, double turnIncrement) {
        this.velIncrement = ActionArgs.nonNegative(getName(), "velIncrement", velIncrement);
        this.turnIncrement = ActionArgs.nonNegative(getName(), "turnIncrement", turnIncrement);
    }

    /** The up arrow: faster forwards (or slower backwards) by the velocity increment. */
    public synchronized void up() {
        deltaVel += velIncrement;
    }

    /** The down arrow: slower forwards (or faster backwards) by the velocity increment. */
    public synchronized void down() {
        deltaVel -= velIncrement;
    }

    /** The left arrow: turn left by the turn increment more, at most the maximum turn amount. */
    public synchronized void left() {
        turnAmount = Math.min(turnAmount + turnIncrement, turnAmountMax);
    }

    /** The right arrow: turn right by the turn increment more, at most the maximum turn amount. */
    public synchronized void right() {
        turnAmount = Math.max(turnAmount - turnIncrement, -turnAmountMax);
    }

    /** The space bar: speed and turn back to 0. */
    public synchronized void space() {
        speedReset = false;
        desiredSpeed = 0;
        turnAmount = 0;
    }

    /** @return the speed it asked for last, mm/s */
    public synchronized double getDesiredSpeed() {
        return desiredSpeed;
    }

    /** As ARIA's: a keydrive switched off gives up its keys and forgets its speed and turn. */
    @Override
    public synchronized void deactivate() {
        if (isActive()) {
            giveUpKeys();
        }
        super.deactivate();
        desiredSpeed = 0;
        turnAmount = 0;
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        if (Math.abs(currentDesired.getVelStrength() - 1.0) < 1e-13) {
            speedReset = true;
        }
        double robotVel = getRobot().getVel();
        if (speedReset && desiredSpeed > 0 && desiredSpeed > robotVel) {
            desiredSpeed = robotVel;
        }
        if (speedReset && desiredSpeed < 0 && desiredSpeed < robotVel) {
            desiredSpeed = robotVel;
        }
        speedReset = false;
        if (currentDesired.getMaxVelStrength() != 0 && desiredSpeed > currentDesired.getMaxVel()) {
            desiredSpeed = currentDesired.getMaxVel();
        }
        if (currentDesired.getMaxNegVelStrength() != 0 && desiredSpeed < currentDesired.getMaxNegVel()) {
            desiredSpeed = currentDesired.getMaxNegVel();
        }
        desiredSpeed = Math.max(-transVelMax, Math.min(transVelMax, desiredSpeed + deltaVel));
        desired.setVel(desiredSpeed);
        deltaVel = 0;
        desired.setDeltaHeading(turnAmount);
        turnAmount = 0;
        return desired;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
