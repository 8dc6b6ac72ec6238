package robosim.aria;

/**
 * Drives from the arrow keys, as ARIA's {@code ArActionKeydrive} (ArActionKeydrive.cpp). ARIA's
 * key handler calls {@link #up()}, {@link #down()}, {@link #left()}, {@link #right()} and
 * {@link #space()} on each key press; RoboSim has no key handler, so whatever reads the keys (the
 * RemoteControl's window, with {@code --keydrive}) calls them, from any thread.
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

    /** As ARIA's: a keydrive switched off forgets its speed and turn. */
    @Override
    public synchronized void deactivate() {
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
