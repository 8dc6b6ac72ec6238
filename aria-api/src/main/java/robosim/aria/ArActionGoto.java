package robosim.aria;

/**
 * Drives naively towards a goal pose, as ARIA's {@code ArActionGoto} (ArActionGoto.cpp, a class
 * ARIA itself marks as superseded by {@link ArActionGotoStraight}): it points at the goal and drives
 * at sqrt(2 · 200 · distance) mm/s, at most its speed; within the close distance it asks for 0, and
 * once the robot is within the close distance and slower than 5 mm/s the goal is achieved and the
 * action asks for nothing more.
 *
 * <p>When an action of higher priority holds the maximum velocity below the speed to turn at
 * (something is in the way), it turns by the turn amount each cycle instead of pointing at the goal,
 * and turns back once it may go faster again; the side it turns to flips whenever the goal is more
 * than 120° off its heading. It does not avoid obstacles by itself: put limiters above it.
 *
 * <pre>{@code
 * ArActionGoto gotoGoal = new ArActionGoto("goto", new ArPose(2500, 0, 0), 100, 400, 150, 7);
 * robot.addAction(gotoGoal, 50);
 * ... gotoGoal.haveAchievedGoal() ...
 * }</pre>
 */
public class ArActionGoto extends ArAction {
    /** ARIA's default close distance, mm. */
    public static final double DEFAULT_CLOSE_DIST = 100;
    /** ARIA's default speed, mm/s. */
    public static final double DEFAULT_SPEED = 400;
    /** ARIA's default speed below which it turns away, mm/s. */
    public static final double DEFAULT_SPEED_TO_TURN_AT = 150;
    /** ARIA's default turn amount, degrees. */
    public static final double DEFAULT_TURN_AMOUNT = 7;

    private enum State { NO_GOAL, ACHIEVED_GOAL, GOING_TO_GOAL }

    private final ArActionDesired desired = new ArActionDesired();
    private ArPose goal;
    private double closeDist;
    private double speed;
    private final double speedToTurnAt;
    private final double turnAmount;
    private double curTurnDir = 1;
    private State state;

    /** A goto named {@code goto} with ARIA's defaults, going to the origin. */
    public ArActionGoto() {
        this("goto");
    }

    /** @param name the action's name; ARIA's defaults, going to the origin */
    public ArActionGoto(String name) {
        this(name, new ArPose(), DEFAULT_CLOSE_DIST, DEFAULT_SPEED, DEFAULT_SPEED_TO_TURN_AT, DEFAULT_TURN_AMOUNT);
    }

    /**
     * @param name the action's name
     * @param goal where to go; ARIA's other defaults
     */
    public ArActionGoto(String name, ArPose goal) {
        this(name, goal, DEFAULT_CLOSE_DIST, DEFAULT_SPEED, DEFAULT_SPEED_TO_TURN_AT, DEFAULT_TURN_AMOUNT);
    }

    /**
     * @param name          the action's name
     * @param goal          where to go (ARIA's goto starts going at once)
     * @param closeDist     how close to the goal counts as there, mm
     * @param speed         the fastest it drives, mm/s
     * @param speedToTurnAt a maximum velocity from higher priorities below this means something is
     *                      in the way: turn, mm/s
     * @param turnAmount    how far it turns each cycle when something is in the way, degrees
     */
    public ArActionGoto(String name, ArPose goal, double closeDist, double speed, double speedToTurnAt,
            double turnAmount) {
        super(name, "Goes to the given goal.");
        this.closeDist = ActionArgs.nonNegative(name, "closeDist", closeDist);
        this.speed = ActionArgs.nonNegative(name, "speed", speed);
        this.speedToTurnAt = ActionArgs.nonNegative(name, "speedToTurnAt", speedToTurnAt);
        this.turnAmount = ActionArgs.finite(name, "turnAmount", turnAmount);
        setGoal(goal);
    }

    /** @return whether the robot got within the close distance of the goal and stopped */
    public synchronized boolean haveAchievedGoal() {
        return state == State.ACHIEVED_GOAL;
    }

    /**
     * Forgets the goal: the action asks for nothing from the next cycle on, and the motion asked for
     * last goes on until another action (an {@code ArActionStop} below it, say) asks otherwise.
     */
    public synchronized void cancelGoal() {
        state = State.NO_GOAL;
    }

    /** @param goal a new goal, to go to from the next cycle on */
    public synchronized void setGoal(ArPose goal) {
        this.goal = ActionArgs.pose(getName(), "goal", goal);
        state = State.GOING_TO_GOAL;
        curTurnDir = 1;
    }

    /** @return the goal (a copy) */
    public synchronized ArPose getGoal() {
        return new ArPose(goal.getX(), goal.getY(), goal.getTh());
    }

    /** @param closeDist how close to the goal counts as there, mm */
    public synchronized void setCloseDist(double closeDist) {
        this.closeDist = ActionArgs.nonNegative(getName(), "closeDist", closeDist);
    }

    /** @return how close to the goal counts as there, mm */
    public synchronized double getCloseDist() {
        return closeDist;
    }

    /** @param speed the fastest it drives, mm/s */
    public synchronized void setSpeed(double speed) {
        this.speed = ActionArgs.nonNegative(getName(), "speed", speed);
    }

    /** @return the fastest it drives, mm/s */
    public synchronized double getSpeed() {
        return speed;
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        if (state != State.GOING_TO_GOAL) {
            return null;
        }
        ArRobot robot = getRobot();
        ArPose at = robot.getPose();
        double dist = at.findDistanceTo(goal);
        if (dist < closeDist && Math.abs(robot.getVel()) < 5) {
            return achieved();
        }
        double angle = at.findAngleTo(goal);
        if (Math.abs(ArMath.subAngle(angle, at.getTh())) > 120) {
            curTurnDir = -curTurnDir;
        }
        if (currentDesired.getMaxVelStrength() > 0 && currentDesired.getMaxVel() < speedToTurnAt) {
            desired.setDeltaHeading(turnAmount * curTurnDir);
        } else if (Math.abs(ArMath.subAngle(angle, ArMath.addAngle(-turnAmount * curTurnDir, at.getTh())))
                > turnAmount / 2) {
            desired.setHeading(angle);
        } else {
            desired.setDeltaHeading(-turnAmount * curTurnDir);
        }
        if (dist < closeDist) {
            desired.setVel(0);
        } else {
            desired.setVel(Math.min(Math.sqrt(dist * 200 * 2), speed));
        }
        return desired;
    }

    private ArActionDesired achieved() {
        state = State.ACHIEVED_GOAL;
        desired.setVel(0);
        desired.setDeltaHeading(0);
        return desired;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
