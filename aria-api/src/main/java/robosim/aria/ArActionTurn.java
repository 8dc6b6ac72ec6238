package robosim.aria;

/**
 * Turns away when the robot has been slowed, as ARIA's {@code ArActionTurn} (ArActionTurn.cpp):
 * meant to sit below a stack of limiters, so that the robot wanders. While the robot goes no faster
 * than the speed to start turning, it asks for a delta heading that grows from 0 at that speed to
 * the full turn amount at the speed of a full turn and below. It turns away from the closest
 * current reading of its range devices within 90° either side of ahead, if one lies nearer than
 * 3 m, else (or without range devices) to the left, and keeps turning that way until the robot speeds up past the start speed
 * again.
 */
public class ArActionTurn extends ArAction {
    /** ARIA's default speed at which turning starts, mm/s. */
    public static final double DEFAULT_SPEED_START_TURN = 200;
    /** ARIA's default speed at and below which it turns the full amount, mm/s. */
    public static final double DEFAULT_SPEED_FULL_TURN = 100;
    /** ARIA's default turn amount, degrees. */
    public static final double DEFAULT_TURN_AMOUNT = 15;
    /** How near the closest reading must be for it to choose the side, mm (ARIA's 3000). */
    public static final double SIDE_CHOICE_RANGE = 3000;

    private final ArActionDesired desired = new ArActionDesired();
    private final double speedStart;
    private final double speedFull;
    private final double turnAmount;
    private int turning;

    /** A turn named {@code turn} with ARIA's defaults. */
    public ArActionTurn() {
        this("turn", DEFAULT_SPEED_START_TURN, DEFAULT_SPEED_FULL_TURN, DEFAULT_TURN_AMOUNT);
    }

    /** @param name the action's name; ARIA's defaults */
    public ArActionTurn(String name) {
        this(name, DEFAULT_SPEED_START_TURN, DEFAULT_SPEED_FULL_TURN, DEFAULT_TURN_AMOUNT);
    }

    /**
     * @param name           the action's name
     * @param speedStartTurn at or below this speed it starts turning, mm/s
     * @param speedFullTurn  below this speed it turns the full amount, mm/s; less than the start speed
     * @param turnAmount     the full delta heading, degrees
     */
    public ArActionTurn(String name, double speedStartTurn, double speedFullTurn, double turnAmount) {
        super(name, "Turns the robot depending on actions by higher priority actions.");
        this.speedStart = ActionArgs.finite(name, "speedStartTurn", speedStartTurn);
        this.speedFull = ActionArgs.finite(name, "speedFullTurn", speedFullTurn);
        if (speedFullTurn >= speedStartTurn) {
            throw new IllegalArgumentException(speedFullTurn + " was supplied for speedFullTurn of " + name
                    + ": it must be less than speedStartTurn (" + speedStartTurn + ")");
        }
        this.turnAmount = ActionArgs.finite(name, "turnAmount", turnAmount);
    }

    /** @return which way it is turning: 1 left, -1 right, 0 not turning */
    public synchronized int getTurning() {
        return turning;
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        ArRobot robot = getRobot();
        double vel = robot.getVel();
        if (vel > speedStart) {
            turning = 0;
            return null;
        }
        double amount = vel < speedFull ? turnAmount : (speedStart - vel) / (speedStart - speedFull) * turnAmount;
        if (turning == 0) {
            double[] angle = new double[1];
            double closest = robot.checkRangeDevicesCurrentPolar(-90, 90, angle);
            // with no range device ARIA reads an angle never set; RoboSim turns left then, as for nothing near
            turning = closest >= 0 && closest < SIDE_CHOICE_RANGE && angle[0] > 0 ? -1 : 1;
        }
        desired.setDeltaHeading(amount * turning);
        return desired;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
