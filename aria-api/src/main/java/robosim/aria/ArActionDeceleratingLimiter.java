package robosim.aria;

/**
 * Slows the robot and raises its deceleration so that it stops short of what its range devices
 * see, as ARIA's {@code ArActionDeceleratingLimiter} (ArActionDeceleratingLimiter.cpp).
 *
 * <p>Each cycle (unless the robot is going the other way faster than 100 mm/s) it finds the closest
 * current reading of the robot's range devices in a box ahead (behind, for {@link LimiterType#BACKWARDS}):
 * as wide as the robot plus a side clearance on each side, as long as half the robot plus the
 * clearance, the padding and 16 m of look-ahead. The side clearance and padding are their slow-speed
 * values at or below the slow speed, their fast-speed values at or above the fast speed, and in
 * between in proportion. The room left is that distance less half the robot's length, the
 * clearance and the padding.
 * <ul>
 * <li>If a reading lies within the clearance itself (in the inner box, of the slow-speed side
 *     clearance) while the robot moves faster than 5 mm/s, it asks for a maximum velocity of 0 in its
 *     direction and a velocity of 0 (and, faster than 100 mm/s, the maximum emergency deceleration,
 *     or the preferred deceleration when that is 0).</li>
 * <li>Else, if the room left is more than the robot needs to stop at its own deceleration, it asks
 *     for nothing.</li>
 * <li>Else it asks for a maximum velocity of 0 in its direction and, if stopping in the room left
 *     takes more than the robot's deceleration (and more than a higher priority already asks for),
 *     a deceleration: what stopping within the clearance needs when that is more than the preferred
 *     deceleration, else at most the preferred one; never more than a maximum emergency deceleration
 *     set above 1.</li>
 * </ul>
 *
 * <p>As in ARIA, a robot with no range device attached has nothing to measure by (the box check
 * answers -1), so the limiter holds it still: attach an {@link ArSonarDevice} or a laser first.
 *
 * <p>Where RoboSim differs: the lateral types are accepted but ask for nothing, since no RoboSim
 * robot moves sideways ({@link ArActionDesired} has no lateral channels); RoboSim has no e-stop
 * command, so {@code useEStop} only logs, and the stop goes through the desire as without it; the
 * robot's top deceleration from its firmware configuration (which ARIA uses when no maximum emergency
 * deceleration is set) is not known, so the preferred deceleration stands in for it.
 */
public class ArActionDeceleratingLimiter extends ArAction {
    /** Which way the limiter guards. */
    public enum LimiterType {
        /** Limit forwards. */
        FORWARDS,
        /** Limit backwards. */
        BACKWARDS,
        /** Limit lateral left: asks for nothing in RoboSim. */
        LATERAL_LEFT,
        /** Limit lateral right: asks for nothing in RoboSim. */
        LATERAL_RIGHT
    }

    /** How far beyond the clearance and padding it looks, mm (ARIA's 16000). */
    public static final double LOOK_AHEAD = 16000;

    private final ArActionDesired desired = new ArActionDesired();
    private LimiterType type;
    private double clearance;
    private double sideClearanceAtSlowSpeed;
    private double paddingAtSlowSpeed;
    private double slowSpeed;
    private double sideClearanceAtFastSpeed;
    private double paddingAtFastSpeed;
    private double fastSpeed;
    private double preferredDecel;
    private boolean useEStop;
    private double maxEmergencyDecel;
    private boolean useLocationDependentDevices = true;
    private boolean stopRotationToo;
    private boolean lastStopped;

    /** A forwards limiter named {@code limitAndDecel} with ARIA's default parameters. */
    public ArActionDeceleratingLimiter() {
        this("limitAndDecel", LimiterType.FORWARDS);
    }

    /** @param name the action's name; a forwards limiter with ARIA's default parameters */
    public ArActionDeceleratingLimiter(String name) {
        this(name, LimiterType.FORWARDS);
    }

    /**
     * @param name the action's name
     * @param type which way it guards; ARIA's default parameters (see {@link #setParameters()})
     */
    public ArActionDeceleratingLimiter(String name, LimiterType type) {
        super(name, "Slows the robot down and cranks up deceleration so as not to hit anything in front of it.");
        setType(type);
        setParameters();
    }

    /**
     * ARIA's defaults: clearance 100 mm; at slow speed (200 mm/s) side clearance 50 mm and padding
     * 50 mm; at fast speed (1000 mm/s) side clearance 400 mm and padding 300 mm; preferred
     * deceleration 600 mm/s²; no e-stop; maximum emergency deceleration 0 (none).
     */
    public void setParameters() {
        setParameters(100, 50, 50, 200, 400, 300, 1000, 600, false, 0);
    }

    /**
     * @param clearance                distance it keeps free ahead, mm
     * @param sideClearanceAtSlowSpeed distance it keeps free on the sides at slow speed or slower, mm
     * @param paddingAtSlowSpeed       distance beyond the clearance it tries to stop at, at slow speed, mm
     * @param slowSpeed                what counts as slow, mm/s
     * @param sideClearanceAtFastSpeed distance it keeps free on the sides at fast speed or faster, mm
     * @param paddingAtFastSpeed       distance beyond the clearance it tries to stop at, at fast speed, mm
     * @param fastSpeed                what counts as fast, mm/s; more than slowSpeed
     * @param preferredDecel           the deceleration it uses unless the clearance needs more, mm/s²
     * @param useEStop                 ARIA's emergency stop when something is within the clearance
     *                                 (only logged in RoboSim)
     * @param maxEmergencyDecel        the most deceleration it ever asks for, mm/s²; 0: no bound
     */
    public synchronized void setParameters(double clearance, double sideClearanceAtSlowSpeed,
            double paddingAtSlowSpeed, double slowSpeed, double sideClearanceAtFastSpeed, double paddingAtFastSpeed,
            double fastSpeed, double preferredDecel, boolean useEStop, double maxEmergencyDecel) {
        String n = getName();
        this.clearance = ActionArgs.nonNegative(n, "clearance", clearance);
        this.sideClearanceAtSlowSpeed = ActionArgs.nonNegative(n, "sideClearanceAtSlowSpeed", sideClearanceAtSlowSpeed);
        this.paddingAtSlowSpeed = ActionArgs.nonNegative(n, "paddingAtSlowSpeed", paddingAtSlowSpeed);
        this.slowSpeed = ActionArgs.nonNegative(n, "slowSpeed", slowSpeed);
        this.sideClearanceAtFastSpeed = ActionArgs.nonNegative(n, "sideClearanceAtFastSpeed", sideClearanceAtFastSpeed);
        this.paddingAtFastSpeed = ActionArgs.nonNegative(n, "paddingAtFastSpeed", paddingAtFastSpeed);
        this.fastSpeed = ActionArgs.nonNegative(n, "fastSpeed", fastSpeed);
        if (fastSpeed <= slowSpeed) {
            throw new IllegalArgumentException(fastSpeed + " was supplied for fastSpeed of " + n
                    + ": it must be more than slowSpeed (" + slowSpeed + ")");
        }
        this.preferredDecel = ActionArgs.positive(n, "preferredDecel", preferredDecel);
        this.useEStop = useEStop;
        this.maxEmergencyDecel = ActionArgs.nonNegative(n, "maxEmergencyDecel", maxEmergencyDecel);
    }

    /** @return which way it guards */
    public synchronized LimiterType getType() {
        return type;
    }

    /** @param type which way it guards */
    public synchronized void setType(LimiterType type) {
        if (type == null) {
            throw new IllegalArgumentException("no type was supplied for " + getName()
                    + ": it is FORWARDS, BACKWARDS, LATERAL_LEFT or LATERAL_RIGHT");
        }
        this.type = type;
    }

    /** @return whether location-dependent devices count (ARIA's flag; RoboSim's devices are all counted) */
    public synchronized boolean getUseLocationDependentDevices() {
        return useLocationDependentDevices;
    }

    /** @param use whether location-dependent devices count (kept for ARIA's API; RoboSim has none) */
    public synchronized void setUseLocationDependentDevices(boolean use) {
        useLocationDependentDevices = use;
    }

    /** @param stopRotationToo whether a stop within the clearance also asks for no rotation */
    public synchronized void setStopRotationToo(boolean stopRotationToo) {
        this.stopRotationToo = stopRotationToo;
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        if (type == LimiterType.LATERAL_LEFT || type == LimiterType.LATERAL_RIGHT) {
            return null;
        }
        ArRobot robot = getRobot();
        boolean forwards = type == LimiterType.FORWARDS;
        double vel = robot.getVel();
        if (forwards ? vel < -100 : vel > 100) {
            return null;
        }
        double absVel = Math.abs(vel);
        double side;
        double padding;
        if (absVel <= slowSpeed) {
            side = sideClearanceAtSlowSpeed;
            padding = paddingAtSlowSpeed;
        } else if (absVel >= fastSpeed) {
            side = sideClearanceAtFastSpeed;
            padding = paddingAtFastSpeed;
        } else {
            double f = (absVel - slowSpeed) / (fastSpeed - slowSpeed);
            side = (sideClearanceAtFastSpeed - sideClearanceAtSlowSpeed) * f + sideClearanceAtSlowSpeed;
            padding = (paddingAtFastSpeed - paddingAtSlowSpeed) * f + paddingAtSlowSpeed;
        }
        double halfLength = robot.getRobotLength() / 2.0;
        double halfWidth = robot.getRobotWidth() / 2.0;
        double sign = forwards ? 1 : -1;
        double dist = robot.checkRangeDevicesCurrentBox(0, -(halfWidth + side),
                sign * (halfLength + clearance + padding + LOOK_AHEAD), halfWidth + side, null)
                - halfLength - clearance - padding;
        double distInner = robot.checkRangeDevicesCurrentBox(0, -(halfWidth + sideClearanceAtSlowSpeed),
                sign * (halfLength + clearance + LOOK_AHEAD), halfWidth + sideClearanceAtSlowSpeed, null)
                - halfLength - clearance;
        if (distInner < 1 && absVel > 5) {
            return stopWithinClearance(forwards, absVel, distInner);
        }
        if (dist > absVel * absVel / 2.0 / robot.getTransDecel()) {
            return null;
        }
        lastStopped = false;
        double deceleration = -absVel * absVel / dist / 2.0;
        double decelerationInner = -absVel * absVel / distInner / 2.0;
        if (Math.abs(deceleration) > Math.abs(robot.getTransDecel())
                && (currentDesired.getTransDecelStrength() < ArActionDesired.MIN_STRENGTH
                        || Math.abs(deceleration) > Math.abs(currentDesired.getTransDecel()))) {
            desired.setTransDecel(decelerationFor(Math.abs(deceleration), Math.abs(decelerationInner)));
        }
        limitVel(forwards);
        return desired;
    }

    /** ARIA's choice among the stopping deceleration, the inner one, the preferred and the emergency bound. */
    private double decelerationFor(double decel, double decelInner) {
        boolean bounded = Math.abs(maxEmergencyDecel) > 1;
        if (bounded && decelInner > maxEmergencyDecel) {
            return maxEmergencyDecel;
        } else if (decelInner > preferredDecel) {
            return decelInner;
        } else if (bounded && decel > maxEmergencyDecel) {
            return maxEmergencyDecel;
        } else if (decel > preferredDecel) {
            return preferredDecel;
        }
        return decel;
    }

    private ArActionDesired stopWithinClearance(boolean forwards, double absVel, double distInner) {
        if (absVel > 100) {
            if (useEStop) {
                ArLogs.info(getName() + ": would e-stop (RoboSim has no e-stop; stopping at the emergency"
                        + " deceleration): a reading lies within the clearance");
            }
            desired.setTransDecel(Math.abs(maxEmergencyDecel) > 1 ? maxEmergencyDecel : preferredDecel);
        }
        lastStopped = true;
        limitVel(forwards);
        desired.setVel(0);
        if (stopRotationToo) {
            desired.setRotVel(0);
        }
        return desired;
    }

    private void limitVel(boolean forwards) {
        if (forwards) {
            desired.setMaxVel(0);
        } else {
            desired.setMaxNegVel(0);
        }
    }

    /** @return whether its last firing stopped the robot for something within the clearance */
    public synchronized boolean isStoppedWithinClearance() {
        return lastStopped;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
