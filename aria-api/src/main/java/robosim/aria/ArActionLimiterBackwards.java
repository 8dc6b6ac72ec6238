package robosim.aria;

/**
 * Limits the backward speed by what is behind, as ARIA's ArActionLimiterBackwards.cpp: it looks in
 * a box behind the robot (distances are negative, behind) for the nearest reading, less the robot's
 * radius. Nearer than the stop distance it sets the maximum backward velocity to 0; farther than the
 * slow distance, to the maximum backwards speed; between, scaled from 0 to it.
 */
public class ArActionLimiterBackwards extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();
    private final double stopDistance;
    private final double slowDistance;
    private final double maxBackwardsSpeed;
    private final double widthRatio;

    /** ARIA's defaults: "speed limiter", stop at −250 mm, slow from −600 mm, −250 mm/s, width ratio 1.5. */
    public ArActionLimiterBackwards() {
        this("speed limiter", -250, -600, -250, 1.5);
    }

    /** @param name the action's name; ARIA's other defaults */
    public ArActionLimiterBackwards(String name) {
        this(name, -250, -600, -250, 1.5);
    }

    /** @param name the action's name @param stopDistance distance at which to stop, mm (negative) */
    public ArActionLimiterBackwards(String name, double stopDistance) {
        this(name, stopDistance, -600, -250, 1.5);
    }

    /**
     * @param name         the action's name
     * @param stopDistance distance at which to stop, mm (negative)
     * @param slowDistance distance at which to slow down, mm (negative)
     */
    public ArActionLimiterBackwards(String name, double stopDistance, double slowDistance) {
        this(name, stopDistance, slowDistance, -250, 1.5);
    }

    /**
     * @param name              the action's name
     * @param stopDistance      distance at which to stop, mm (negative)
     * @param slowDistance      distance at which to slow down, mm (negative)
     * @param maxBackwardsSpeed the backward speed allowed beyond the slow distance, mm/s; width ratio 1.5
     */
    public ArActionLimiterBackwards(String name, double stopDistance, double slowDistance, double maxBackwardsSpeed) {
        this(name, stopDistance, slowDistance, maxBackwardsSpeed, 1.5);
    }

    /**
     * @param name              the action's name
     * @param stopDistance      distance at which to stop, mm (negative: behind)
     * @param slowDistance      distance at which to slow down, mm (negative)
     * @param maxBackwardsSpeed the backward speed allowed beyond the slow distance, mm/s
     * @param widthRatio        the box's width as a multiple of the robot's width
     */
    public ArActionLimiterBackwards(String name, double stopDistance, double slowDistance, double maxBackwardsSpeed,
                                    double widthRatio) {
        super(name, "Slows the robot down so as not to hit anything behind it.");
        this.stopDistance = stopDistance;
        this.slowDistance = slowDistance;
        this.maxBackwardsSpeed = maxBackwardsSpeed;
        this.widthRatio = widthRatio;
    }

    @Override
    public ArActionDesired fire(ArActionDesired currentDesired) {
        ArRobot robot = getRobot();
        double slowStop = Math.max(stopDistance, slowDistance);
        double halfWidth = robot.getRobotWidth() / 2.0 * widthRatio;
        desired.reset();
        double dist = robot.checkRangeDevicesCurrentBox(0, -halfWidth, slowStop - robot.getRobotLength(), halfWidth)
                - robot.getRobotRadius();
        if (dist < -stopDistance) {
            desired.setMaxNegVel(0);
        } else if (dist > -slowDistance) {
            desired.setMaxNegVel(-Math.abs(maxBackwardsSpeed));
        } else {
            desired.setMaxNegVel(-Math.abs(maxBackwardsSpeed) * ((-dist - stopDistance) / (slowDistance - stopDistance)));
        }
        return desired;
    }

    @Override
    public ArActionDesired getDesired() {
        return desired;
    }
}
