package robosim.aria;

/**
 * Drives a given distance, as ARIA's {@code ArActionDriveDistance} (ArActionDriveDistance.cpp):
 * it adds up the way the robot's pose travels each cycle and asks for sqrt(2 · deceleration ·
 * distance to go) mm/s, at most its speed, backwards for a negative distance, with no rotation.
 * Once the way is travelled and the robot is slower than 5 mm/s the distance is achieved and the
 * action asks for nothing more. It reads no sensors: put limiters above it.
 *
 * <p>ARIA measures the way by the encoder pose by default; RoboSim's pose is the robot's odometry,
 * so both settings of {@code useEncoders} measure the same way.
 */
public class ArActionDriveDistance extends ArAction {
    /** ARIA's default speed, mm/s. */
    public static final double DEFAULT_SPEED = 400;
    /** ARIA's default deceleration, mm/s². */
    public static final double DEFAULT_DECELERATION = 200;

    private enum State { NO_DISTANCE, ACHIEVED_DISTANCE, GOING_DISTANCE }

    private final ArActionDesired desired = new ArActionDesired();
    private double speed;
    private double deceleration;
    private double distance;
    private boolean useEncoders;
    private double distTravelled;
    private ArPose lastPose = new ArPose();
    private State state = State.NO_DISTANCE;

    /** A drive named {@code driveDistance} with ARIA's defaults. */
    public ArActionDriveDistance() {
        this("driveDistance", DEFAULT_SPEED, DEFAULT_DECELERATION);
    }

    /** @param name the action's name; ARIA's defaults */
    public ArActionDriveDistance(String name) {
        this(name, DEFAULT_SPEED, DEFAULT_DECELERATION);
    }

    /**
     * @param name         the action's name
     * @param speed        the fastest it drives, mm/s
     * @param deceleration how it slows towards the end, mm/s²
     */
    public ArActionDriveDistance(String name, double speed, double deceleration) {
        super(name, "Drives a given distance.");
        this.speed = ActionArgs.nonNegative(name, "speed", speed);
        this.deceleration = ActionArgs.positive(name, "deceleration", deceleration);
    }

    /** @return whether the distance was travelled and the robot stopped */
    public synchronized boolean haveAchievedDistance() {
        return state == State.ACHIEVED_DISTANCE;
    }

    /** Forgets the distance: the action asks for nothing from the next cycle on. */
    public synchronized void cancelDistance() {
        state = State.NO_DISTANCE;
    }

    /** @param distance how far to drive from here, mm; negative backwards */
    public void setDistance(double distance) {
        setDistance(distance, true);
    }

    /**
     * Starts driving a distance; the action must have been added to a robot.
     *
     * @param distance    how far to drive from here, mm; negative backwards
     * @param useEncoders ARIA's choice of pose to measure by (the same pose in RoboSim)
     */
    public synchronized void setDistance(double distance, boolean useEncoders) {
        ArRobot robot = getRobot();
        if (robot == null) {
            throw new IllegalStateException("setDistance on " + getName()
                    + ": the action has no robot; add it with robot.addAction first");
        }
        this.distance = ActionArgs.finite(getName(), "distance", distance);
        this.useEncoders = useEncoders;
        lastPose = robot.getPose();
        distTravelled = 0;
        state = State.GOING_DISTANCE;
    }

    /** @return the distance set last, mm */
    public synchronized double getDistance() {
        return distance;
    }

    /** @return whether the distance was set to be measured by the encoders */
    public synchronized boolean usingEncoders() {
        return useEncoders;
    }

    /** Sets ARIA's default speed, 400 mm/s. */
    public void setSpeed() {
        setSpeed(DEFAULT_SPEED);
    }

    /** @param speed the fastest it drives, mm/s */
    public synchronized void setSpeed(double speed) {
        this.speed = ActionArgs.nonNegative(getName(), "speed", speed);
    }

    /** @return the fastest it drives, mm/s */
    public synchronized double getSpeed() {
        return speed;
    }

    /** Sets ARIA's default deceleration, 200 mm/s². */
    public void setDeceleration() {
        setDeceleration(DEFAULT_DECELERATION);
    }

    /** @param deceleration how it slows towards the end, mm/s² */
    public synchronized void setDeceleration(double deceleration) {
        this.deceleration = ActionArgs.positive(getName(), "deceleration", deceleration);
    }

    /** @return how it slows towards the end, mm/s² */
    public synchronized double getDeceleration() {
        return deceleration;
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        if (state != State.GOING_DISTANCE) {
            return null;
        }
        ArRobot robot = getRobot();
        ArPose at = robot.getPose();
        distTravelled += at.findDistanceTo(lastPose);
        lastPose = at;
        double distToGo = Math.abs(distance) - distTravelled;
        if (distToGo <= 0 && Math.abs(robot.getVel()) < 5) {
            state = State.ACHIEVED_DISTANCE;
            desired.setVel(0);
            desired.setRotVel(0);
            return desired;
        }
        desired.setRotVel(0);
        if (distToGo <= 0) {
            desired.setVel(0);
        } else {
            double vel = Math.min(Math.sqrt(distToGo * deceleration * 2), speed);
            desired.setVel(distance < 0 ? -vel : vel);
        }
        return desired;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
