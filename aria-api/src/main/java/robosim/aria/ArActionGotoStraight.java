package robosim.aria;

/**
 * Drives straight to a goal, as ARIA's {@code ArActionGotoStraight} (ArActionGotoStraight.cpp):
 * each cycle it asks for the heading to the goal (its opposite when backing) and a velocity of
 * sqrt(2 · 200 · distance) mm/s, at most its speed (negative when backing). The goal is achieved
 * once the robot is slower than 5 mm/s and either within the close distance of the goal or, in
 * just-distance mode (ARIA's default), has travelled the distance the goal was away when it was
 * set; the action then asks for nothing more.
 *
 * <p>With a turn threshold, it turns in place (at the turn speed, if one is set) while the goal is
 * more than the threshold off the heading it had last cycle; with a maximum rotational velocity,
 * it turns no faster while driving. It reads no sensors: put limiters above it.
 *
 * <p>ARIA's encoder goals ({@code setEncoderGoal}) are left out: RoboSim's pose is the robot's
 * odometry, with no separate encoder pose.
 */
public class ArActionGotoStraight extends ArAction {
    /** ARIA's default speed, mm/s. */
    public static final double DEFAULT_SPEED = 400;
    /** ARIA's default close distance, mm. */
    public static final double DEFAULT_CLOSE_DIST = 100;
    /** ARIA's default turn threshold, degrees: never turn in place. */
    public static final double DEFAULT_TURN_THRESHOLD = 360;

    private enum State { NO_GOAL, ACHIEVED_GOAL, GOING_TO_GOAL }

    private final ArActionDesired desired = new ArActionDesired();
    private ArPose goal = new ArPose();
    private double speed;
    private double closeDist = DEFAULT_CLOSE_DIST;
    private double turnThreshold = DEFAULT_TURN_THRESHOLD;
    private double turnSpeed;
    private double maxRotVel;
    private boolean backing;
    private boolean justDistance;
    private double dist;
    private double distTravelled;
    private ArPose lastPose = new ArPose();
    private State state = State.NO_GOAL;

    /** A goto named {@code goto} at ARIA's default speed, with no goal. */
    public ArActionGotoStraight() {
        this("goto", DEFAULT_SPEED);
    }

    /** @param name the action's name; ARIA's default speed */
    public ArActionGotoStraight(String name) {
        this(name, DEFAULT_SPEED);
    }

    /**
     * @param name  the action's name
     * @param speed the fastest it drives, mm/s
     */
    public ArActionGotoStraight(String name, double speed) {
        super(name, "Goes to the given goal.");
        this.speed = ActionArgs.nonNegative(name, "speed", speed);
    }

    /** @return whether the goal was reached and the robot stopped */
    public synchronized boolean haveAchievedGoal() {
        return state == State.ACHIEVED_GOAL;
    }

    /** Forgets the goal: the action asks for nothing from the next cycle on. */
    public synchronized void cancelGoal() {
        state = State.NO_GOAL;
    }

    /**
     * Goes forwards to a goal, in just-distance mode (ARIA's defaults).
     *
     * @param goal the goal, global
     */
    public void setGoal(ArPose goal) {
        setGoal(goal, false, true);
    }

    /**
     * Sets a goal; the action must have been added to a robot.
     *
     * @param goal         the goal, global
     * @param backwards    back up to it
     * @param justDistance done after travelling the distance it is away now, rather than on
     *                     getting within the close distance of it
     */
    public synchronized void setGoal(ArPose goal, boolean backwards, boolean justDistance) {
        ArRobot robot = robot("setGoal");
        this.goal = ActionArgs.pose(getName(), "goal", goal);
        state = State.GOING_TO_GOAL;
        backing = backwards;
        lastPose = robot.getPose();
        dist = lastPose.findDistanceTo(this.goal);
        this.justDistance = justDistance;
        distTravelled = 0;
    }

    /**
     * Goes forwards to a goal given from where the robot is, in just-distance mode.
     *
     * @param dist         how far, mm
     * @param deltaHeading in which direction from the robot's heading, degrees
     */
    public void setGoalRel(double dist, double deltaHeading) {
        setGoalRel(dist, deltaHeading, false, true);
    }

    /**
     * Sets a goal given from where the robot is: {@code dist} away in the direction
     * {@code deltaHeading} off its heading.
     *
     * @param dist         how far, mm
     * @param deltaHeading in which direction from the robot's heading, degrees
     * @param backwards    back up to it
     * @param justDistance see {@link #setGoal(ArPose, boolean, boolean)}
     */
    public synchronized void setGoalRel(double dist, double deltaHeading, boolean backwards, boolean justDistance) {
        ActionArgs.finite(getName(), "dist", dist);
        ActionArgs.finite(getName(), "deltaHeading", deltaHeading);
        ArPose at = robot("setGoalRel").getPose();
        double direction = ArMath.degToRad(at.getTh() + deltaHeading);
        setGoal(new ArPose(at.getX() + dist * Math.cos(direction), at.getY() + dist * Math.sin(direction), at.getTh()),
                backwards, justDistance);
    }

    /** @return the goal (a copy) */
    public synchronized ArPose getGoal() {
        return new ArPose(goal.getX(), goal.getY(), goal.getTh());
    }

    /** @return whether it backs up to the goal */
    public synchronized boolean getBacking() {
        return backing;
    }

    /** @param speed the fastest it drives, mm/s */
    public synchronized void setSpeed(double speed) {
        this.speed = ActionArgs.nonNegative(getName(), "speed", speed);
    }

    /** @return the fastest it drives, mm/s */
    public synchronized double getSpeed() {
        return speed;
    }

    /** Sets ARIA's default close distance, 100 mm. */
    public void setCloseDist() {
        setCloseDist(DEFAULT_CLOSE_DIST);
    }

    /** @param closeDist how close to the goal counts as there when not in just-distance mode, mm */
    public synchronized void setCloseDist(double closeDist) {
        this.closeDist = ActionArgs.nonNegative(getName(), "closeDist", closeDist);
    }

    /** @return how close to the goal counts as there when not in just-distance mode, mm */
    public synchronized double getCloseDist() {
        return closeDist;
    }

    /**
     * @param threshAngle while the goal is more than this off its heading it turns in place rather
     *                    than driving and turning at once, degrees (ARIA warns: below about 20 the
     *                    robot may never settle on the heading)
     */
    public synchronized void setTurnThreshold(double threshAngle) {
        turnThreshold = ActionArgs.nonNegative(getName(), "threshAngle", threshAngle);
    }

    /** @param speed the rotational velocity limit while turning in place, deg/s; 0: the robot's own */
    public synchronized void setTurnSpeed(double speed) {
        turnSpeed = ActionArgs.nonNegative(getName(), "turnSpeed", speed);
    }

    /** @param rv the rotational velocity limit while driving, deg/s; 0: the robot's own */
    public synchronized void setMaxRotVel(double rv) {
        maxRotVel = ActionArgs.nonNegative(getName(), "maxRotVel", rv);
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        if (state != State.GOING_TO_GOAL) {
            return null;
        }
        desired.reset(); // as ARIA's: only what this cycle sets, not what an earlier one did
        ArRobot robot = getRobot();
        ArPose at = robot.getPose();
        distTravelled += at.findDistanceTo(lastPose);
        lastPose = at;
        double distToGo = dist - distTravelled;
        double away = justDistance ? Math.abs(distToGo) : at.findDistanceTo(goal);
        boolean there = justDistance ? distToGo <= 0 : away < closeDist;
        if (there && Math.abs(robot.getVel()) < 5) {
            // ARIA's lines (ArActionGotoStraight::fire), word for word
            if (justDistance) {
                ArLog.log(ArLog.Normal, "%s: Achieved distance to goal (dist=%.2f, robotVel=%.2f)", getName(), distToGo,
                        robot.getVel());
            } else {
                ArLog.log(ArLog.Normal, "%s: Achieved goal (dist=%.2f, closeDist=%.2f, robotVel=%.2f)", getName(), away,
                        closeDist, robot.getVel());
            }
            state = State.ACHIEVED_GOAL;
            desired.setVel(0);
            desired.setDeltaHeading(0);
            return desired;
        }
        double angle = at.findAngleTo(goal);
        if (backing) {
            angle = ArMath.subAngle(angle, 180);
        }
        desired.setHeading(angle);
        if (there) {
            desired.setVel(0);
        } else if (Math.abs(ArMath.subAngle(lastPose.getTh(), angle)) <= turnThreshold) {
            double vel = Math.min(Math.sqrt(away * 200 * 2), speed);
            desired.setVel(backing ? -vel : vel);
            if (maxRotVel > 1e-9) {
                desired.setMaxRotVel(maxRotVel);
            }
        } else if (turnSpeed > 1e-9) {
            desired.setMaxRotVel(turnSpeed);
        }
        return desired;
    }

    private ArRobot robot(String call) {
        ArRobot robot = getRobot();
        if (robot == null) {
            throw new IllegalStateException(call + " on " + getName()
                    + ": the action has no robot; add it with robot.addAction first");
        }
        return robot;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
