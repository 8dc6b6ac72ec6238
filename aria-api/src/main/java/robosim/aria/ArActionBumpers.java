package robosim.aria;

/**
 * Backs away from a bump and turns away from it, as ARIA's ArActionBumpers.cpp: driving forwards
 * (faster than 25 mm/s) with a front bumper pressed, or backwards with a rear one, it drives the
 * other way at the back-off speed for the back-off time (holding still while that side's bumper is
 * pressed too), then turns for at most the turn time to a heading away from the pressed bumpers:
 * each pressed bumper i of n stands for the angle i · 135/n + 135/2n − 135/2 across the bumper, and
 * the robot turns by 67.5° less the mean of those angles, away from them. Bumpers come from the
 * robot's stall value ({@link ArRobot#getStallValue()}); times are simulated.
 */
public class ArActionBumpers extends ArAction {
    /** The spread of angles the bumpers stand for, degrees (ARIA's turn range). */
    static final double TURN_RANGE = 135;
    private static final int BUMP_MASK = 0xff << 1;

    private final ArActionDesired desired = new ArActionDesired();
    private final double backOffSpeed;
    private final int backOffTime;
    private final int turnTime;
    private final boolean setMaximums;
    private boolean firing;
    private double speed;
    private double heading;
    private long startBackMs;

    /** ARIA's defaults: "bumpers", 100 mm/s, 3000 ms back, 3000 ms turn, no maximums. */
    public ArActionBumpers() {
        this("bumpers", 100, 3000, 3000, false);
    }

    /** @param name the action's name; ARIA's other defaults */
    public ArActionBumpers(String name) {
        this(name, 100, 3000, 3000, false);
    }

    /** @param name the action's name @param backOffSpeed speed to back away at, mm/s */
    public ArActionBumpers(String name, double backOffSpeed) {
        this(name, backOffSpeed, 3000, 3000, false);
    }

    /**
     * @param name         the action's name
     * @param backOffSpeed speed to back away at, mm/s
     * @param backOffTime  how long to back away, ms
     */
    public ArActionBumpers(String name, double backOffSpeed, int backOffTime) {
        this(name, backOffSpeed, backOffTime, 3000, false);
    }

    /**
     * @param name         the action's name
     * @param backOffSpeed speed to back away at, mm/s
     * @param backOffTime  how long to back away, ms
     * @param turnTime     how long the turn may take, ms
     */
    public ArActionBumpers(String name, double backOffSpeed, int backOffTime, int turnTime) {
        this(name, backOffSpeed, backOffTime, turnTime, false);
    }

    /**
     * @param name         the action's name
     * @param backOffSpeed speed to back away at, mm/s
     * @param backOffTime  how long to back away, ms
     * @param turnTime     how long the turn may take, ms
     * @param setMaximums  whether to also limit the velocity to the back-off speed while backing away
     */
    public ArActionBumpers(String name, double backOffSpeed, int backOffTime, int turnTime, boolean setMaximums) {
        super(name, "Reacts to the bumpers triggering");
        this.backOffSpeed = backOffSpeed;
        this.backOffTime = backOffTime;
        this.turnTime = turnTime;
        this.setMaximums = setMaximums;
    }

    @Override
    public void activate() {
        firing = false;
        super.activate();
    }

    /**
     * ARIA's {@code findDegreesToTurn}.
     *
     * @param bumpValue  the pressed bumpers, bit i + 1 for bumper i
     * @param numBumpers the bumpers on that side
     * @return degrees to turn: positive to the left
     */
    static double degreesToTurn(int bumpValue, int numBumpers) {
        double total = 0;
        int pressed = 0;
        double each = TURN_RANGE / numBumpers;
        for (int i = 0; i < numBumpers && i < 8; i++) {
            if ((bumpValue & (1 << (i + 1))) != 0) {
                total += i * each + each / 2 - TURN_RANGE / 2;
                pressed++;
            }
        }
        total /= pressed;
        return total < 0 ? -(TURN_RANGE / 2 + total) : TURN_RANGE / 2 - total;
    }

    @Override
    public ArActionDesired fire(ArActionDesired currentDesired) {
        ArRobot robot = getRobot();
        int stall = robot.getStallValue();
        int frontBump = robot.hasFrontBumpers() ? ((stall & 0xff00) >> 8) & BUMP_MASK : 0;
        int rearBump = robot.hasRearBumpers() ? (stall & 0xff) & BUMP_MASK : 0;
        long now = robot.getSimTimeMs();
        desired.reset();
        if (firing) {
            long since = now - startBackMs;
            if (since < backOffTime) {
                boolean blocked = (speed < 0 && rearBump != 0) || (speed > 0 && frontBump != 0);
                desired.setVel(blocked ? 0 : speed);
                desired.setDeltaHeading(0);
                return desired;
            } else if (since < backOffTime + turnTime && Math.abs(ArMath.subAngle(robot.getTh(), heading)) > 3) {
                desired.setVel(0);
                desired.setHeading(heading);
                return desired;
            }
            firing = false;
        }
        if (robot.getVel() > 25) {
            if (frontBump == 0) {
                return null;
            }
            heading = ArMath.addAngle(robot.getTh(), degreesToTurn(frontBump, robot.getNumFrontBumpers()));
            speed = -backOffSpeed;
        } else if (robot.getVel() < -25) {
            if (rearBump == 0) {
                return null;
            }
            heading = ArMath.subAngle(robot.getTh(), degreesToTurn(rearBump, robot.getNumRearBumpers()));
            speed = backOffSpeed;
        } else {
            return null;
        }
        startBackMs = now;
        firing = true;
        desired.setVel(speed);
        desired.setHeading(heading);
        if (setMaximums) {
            if (speed > 0) {
                desired.setMaxVel(speed);
            } else {
                desired.setMaxNegVel(speed);
            }
        }
        return desired;
    }

    @Override
    public ArActionDesired getDesired() {
        return desired;
    }
}
