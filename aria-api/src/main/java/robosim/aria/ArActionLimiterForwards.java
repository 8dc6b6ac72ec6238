package robosim.aria;

/**
 * Limits the forward speed by what is ahead, as ARIA's ArActionLimiterForwards.cpp: it looks in a
 * box ahead of the robot (as wide as the robot times the width ratio, as long as half the robot's
 * length plus the larger of the stop and slow distances) for the nearest reading, less half the
 * robot's length. Nearer than the stop distance it sets the maximum velocity to 0; nearer than the
 * slow distance, to the slow speed scaled from 0 at the stop distance to the slow speed at the slow
 * distance; farther, nothing.
 */
public class ArActionLimiterForwards extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();
    private final ArPose lastReading = new ArPose();
    private volatile double stopDistance;
    private volatile double slowDistance;
    private volatile double slowSpeed;
    private volatile double widthRatio;
    private boolean lastStopped;

    /** ARIA's defaults: "speed limiter", stop at 250 mm, slow from 1000 mm, 200 mm/s, width ratio 1. */
    public ArActionLimiterForwards() {
        this("speed limiter", 250, 1000, 200, 1);
    }

    /** @param name the action's name; ARIA's other defaults */
    public ArActionLimiterForwards(String name) {
        this(name, 250, 1000, 200, 1);
    }

    /** @param name the action's name @param stopDistance distance at which to stop, mm */
    public ArActionLimiterForwards(String name, double stopDistance) {
        this(name, stopDistance, 1000, 200, 1);
    }

    /**
     * @param name         the action's name
     * @param stopDistance distance at which to stop, mm
     * @param slowDistance distance at which to slow down, mm
     */
    public ArActionLimiterForwards(String name, double stopDistance, double slowDistance) {
        this(name, stopDistance, slowDistance, 200, 1);
    }

    /**
     * @param name         the action's name
     * @param stopDistance distance at which to stop, mm
     * @param slowDistance distance at which to slow down, mm
     * @param slowSpeed    speed allowed at the slow distance, mm/s; width ratio 1
     */
    public ArActionLimiterForwards(String name, double stopDistance, double slowDistance, double slowSpeed) {
        this(name, stopDistance, slowDistance, slowSpeed, 1);
    }

    /**
     * @param name         the action's name
     * @param stopDistance distance at which to stop, mm
     * @param slowDistance distance at which to slow down, mm
     * @param slowSpeed    speed allowed at the slow distance, scaled to 0 at the stop distance, mm/s
     * @param widthRatio   the box's width as a multiple of the robot's width
     */
    public ArActionLimiterForwards(String name, double stopDistance, double slowDistance, double slowSpeed,
                                   double widthRatio) {
        super(name, "Slows the robot down so as not to hit anything in front of it.");
        setParameters(stopDistance, slowDistance, slowSpeed, widthRatio);
    }

    /**
     * @param stopDistance distance at which to stop, mm
     * @param slowDistance distance at which to slow down, mm
     * @param slowSpeed    speed allowed at the slow distance, mm/s
     * @param widthRatio   the box's width as a multiple of the robot's width
     */
    public final void setParameters(double stopDistance, double slowDistance, double slowSpeed, double widthRatio) {
        this.stopDistance = stopDistance;
        this.slowDistance = slowDistance;
        this.slowSpeed = slowSpeed;
        this.widthRatio = widthRatio;
    }

    @Override
    public ArActionDesired fire(ArActionDesired currentDesired) {
        ArRobot robot = getRobot();
        double checkDist = Math.max(stopDistance, slowDistance);
        double halfWidth = robot.getRobotWidth() / 2.0 * widthRatio;
        desired.reset();
        double dist = robot.checkRangeDevicesCurrentBox(0, -halfWidth, checkDist + robot.getRobotLength() / 2,
                halfWidth, lastReading) - robot.getRobotLength() / 2;
        if (dist < stopDistance) {
            lastStopped = true;
            desired.setMaxVel(0);
            return desired;
        }
        lastStopped = false;
        if (dist > slowDistance) {
            return null;
        }
        desired.setMaxVel(slowSpeed * ((dist - stopDistance) / (slowDistance - stopDistance)));
        return desired;
    }

    /** @return whether the last firing stopped the robot */
    public boolean getStopped() {
        return lastStopped;
    }

    /** @return the position of the reading that last limited the robot, global mm */
    public ArPose getLastSensorReadingPos() {
        return new ArPose(lastReading.getX(), lastReading.getY(), lastReading.getTh());
    }

    @Override
    public ArActionDesired getDesired() {
        return desired;
    }
}
