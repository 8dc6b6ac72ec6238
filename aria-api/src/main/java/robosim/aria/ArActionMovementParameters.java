package robosim.aria;

/**
 * Sets the maximum velocities and the accelerations for the actions below it, as ARIA's
 * {@code ArActionMovementParameters} (ArActionMovementParameters.cpp): each parameter whose size is
 * at least 1 is asked for, at full strength: maximum forward velocity, maximum backward velocity
 * (given as a positive speed, asked for as negative), translational acceleration and deceleration,
 * maximum rotational velocity, rotational acceleration and deceleration. A parameter under 1 (the
 * default, 0) leaves that limit to the robot. Disabled, it wants nothing, except for one firing after
 * {@link #enableOnceFromSector}.
 *
 * <p>The lateral parameters go into the desire's lateral channels, as ARIA's do; no simulated robot
 * moves sideways, so nothing sends them. {@code overrideFaster} is kept and, as in ARIA's code, not
 * used in firing.
 */
public class ArActionMovementParameters extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();
    private final boolean overrideFaster;
    private final boolean addLatVelIfAvailable;
    private boolean enabled = true;
    private boolean enableOnce;
    private double maxVel, maxNegVel, transAccel, transDecel, maxRotVel, rotAccel, rotDecel;
    private double maxLatVel, latAccel, latDecel;

    /** ARIA's defaults: "MovementParameters", override faster, lateral if available. */
    public ArActionMovementParameters() {
        this("MovementParameters");
    }

    /** @param name the action's name */
    public ArActionMovementParameters(String name) {
        this(name, true);
    }

    /**
     * @param name           the action's name
     * @param overrideFaster ARIA's flag for overriding a faster maximum (kept; unused as in ARIA)
     */
    public ArActionMovementParameters(String name, boolean overrideFaster) {
        this(name, overrideFaster, true);
    }

    /**
     * @param name                 the action's name
     * @param overrideFaster       ARIA's flag for overriding a faster maximum (kept; unused as in ARIA)
     * @param addLatVelIfAvailable whether the lateral parameters count on a robot that moves sideways
     */
    public ArActionMovementParameters(String name, boolean overrideFaster, boolean addLatVelIfAvailable) {
        super(name, "Sets all the max vel and accels/decels");
        this.overrideFaster = overrideFaster;
        this.addLatVelIfAvailable = addLatVelIfAvailable;
        setParameters();
    }

    /** @return whether it fires */
    public synchronized boolean isEnabled() {
        return enabled;
    }

    /** It asks for its limits from now on. */
    public synchronized void enable() {
        enabled = true;
    }

    /** It asks for its limits at the next firing only, though disabled (ARIA's map-sector hook). */
    public synchronized void enableOnceFromSector() {
        enableOnce = true;
    }

    /**
     * As {@link #enableOnceFromSector()}; ARIA's takes the map object, unused.
     *
     * @param mapObject ignored
     */
    public void enableOnceFromSector(Object mapObject) {
        enableOnceFromSector();
    }

    /** It wants nothing from now on. */
    public synchronized void disable() {
        enabled = false;
    }

    /** All parameters 0: the robot's own limits. */
    public void setParameters() {
        setParameters(0, 0, 0, 0, 0, 0, 0, 0, 0, 0);
    }

    /** @param maxVel the maximum forward velocity, mm/s (under 1: none) */
    public void setParameters(double maxVel) {
        setParameters(maxVel, 0, 0, 0, 0, 0, 0, 0, 0, 0);
    }

    /**
     * @param maxVel    the maximum forward velocity, mm/s
     * @param maxNegVel the maximum backward speed, mm/s, positive
     */
    public void setParameters(double maxVel, double maxNegVel) {
        setParameters(maxVel, maxNegVel, 0, 0, 0, 0, 0, 0, 0, 0);
    }

    /**
     * @param maxVel     the maximum forward velocity, mm/s
     * @param maxNegVel  the maximum backward speed, mm/s, positive
     * @param transAccel the translational acceleration, mm/s²
     */
    public void setParameters(double maxVel, double maxNegVel, double transAccel) {
        setParameters(maxVel, maxNegVel, transAccel, 0, 0, 0, 0, 0, 0, 0);
    }

    /**
     * @param maxVel     the maximum forward velocity, mm/s
     * @param maxNegVel  the maximum backward speed, mm/s, positive
     * @param transAccel the translational acceleration, mm/s²
     * @param transDecel the translational deceleration, mm/s²
     */
    public void setParameters(double maxVel, double maxNegVel, double transAccel, double transDecel) {
        setParameters(maxVel, maxNegVel, transAccel, transDecel, 0, 0, 0, 0, 0, 0);
    }

    /**
     * @param maxVel     the maximum forward velocity, mm/s
     * @param maxNegVel  the maximum backward speed, mm/s, positive
     * @param transAccel the translational acceleration, mm/s²
     * @param transDecel the translational deceleration, mm/s²
     * @param rotVelMax  the maximum rotational velocity, deg/s
     */
    public void setParameters(double maxVel, double maxNegVel, double transAccel, double transDecel,
            double rotVelMax) {
        setParameters(maxVel, maxNegVel, transAccel, transDecel, rotVelMax, 0, 0, 0, 0, 0);
    }

    /**
     * @param maxVel     the maximum forward velocity, mm/s
     * @param maxNegVel  the maximum backward speed, mm/s, positive
     * @param transAccel the translational acceleration, mm/s²
     * @param transDecel the translational deceleration, mm/s²
     * @param rotVelMax  the maximum rotational velocity, deg/s
     * @param rotAccel   the rotational acceleration, deg/s²
     */
    public void setParameters(double maxVel, double maxNegVel, double transAccel, double transDecel,
            double rotVelMax, double rotAccel) {
        setParameters(maxVel, maxNegVel, transAccel, transDecel, rotVelMax, rotAccel, 0, 0, 0, 0);
    }

    /**
     * @param maxVel     the maximum forward velocity, mm/s
     * @param maxNegVel  the maximum backward speed, mm/s, positive
     * @param transAccel the translational acceleration, mm/s²
     * @param transDecel the translational deceleration, mm/s²
     * @param rotVelMax  the maximum rotational velocity, deg/s
     * @param rotAccel   the rotational acceleration, deg/s²
     * @param rotDecel   the rotational deceleration, deg/s²
     */
    public void setParameters(double maxVel, double maxNegVel, double transAccel, double transDecel,
            double rotVelMax, double rotAccel, double rotDecel) {
        setParameters(maxVel, maxNegVel, transAccel, transDecel, rotVelMax, rotAccel, rotDecel, 0, 0, 0);
    }

    /**
     * @param maxVel     the maximum forward velocity, mm/s
     * @param maxNegVel  the maximum backward speed, mm/s, positive
     * @param transAccel the translational acceleration, mm/s²
     * @param transDecel the translational deceleration, mm/s²
     * @param rotVelMax  the maximum rotational velocity, deg/s
     * @param rotAccel   the rotational acceleration, deg/s²
     * @param rotDecel   the rotational deceleration, deg/s²
     * @param latVelMax  the maximum lateral velocity, mm/s (no simulated robot moves sideways)
     */
    public void setParameters(double maxVel, double maxNegVel, double transAccel, double transDecel,
            double rotVelMax, double rotAccel, double rotDecel, double latVelMax) {
        setParameters(maxVel, maxNegVel, transAccel, transDecel, rotVelMax, rotAccel, rotDecel, latVelMax, 0, 0);
    }

    /**
     * @param maxVel     the maximum forward velocity, mm/s
     * @param maxNegVel  the maximum backward speed, mm/s, positive
     * @param transAccel the translational acceleration, mm/s²
     * @param transDecel the translational deceleration, mm/s²
     * @param rotVelMax  the maximum rotational velocity, deg/s
     * @param rotAccel   the rotational acceleration, deg/s²
     * @param rotDecel   the rotational deceleration, deg/s²
     * @param latVelMax  the maximum lateral velocity, mm/s
     * @param latAccel   the lateral acceleration, mm/s²
     */
    public void setParameters(double maxVel, double maxNegVel, double transAccel, double transDecel,
            double rotVelMax, double rotAccel, double rotDecel, double latVelMax, double latAccel) {
        setParameters(maxVel, maxNegVel, transAccel, transDecel, rotVelMax, rotAccel, rotDecel, latVelMax, latAccel,
                0);
    }

    /**
     * @param maxVel     the maximum forward velocity, mm/s
     * @param maxNegVel  the maximum backward speed, mm/s, positive
     * @param transAccel the translational acceleration, mm/s²
     * @param transDecel the translational deceleration, mm/s²
     * @param rotVelMax  the maximum rotational velocity, deg/s
     * @param rotAccel   the rotational acceleration, deg/s²
     * @param rotDecel   the rotational deceleration, deg/s²
     * @param latVelMax  the maximum lateral velocity, mm/s
     * @param latAccel   the lateral acceleration, mm/s²
     * @param latDecel   the lateral deceleration, mm/s²
     */
    public synchronized void setParameters(double maxVel, double maxNegVel, double transAccel, double transDecel,
            double rotVelMax, double rotAccel, double rotDecel, double latVelMax, double latAccel, double latDecel) {
        String n = getName();
        this.maxVel = ActionArgs.finite(n, "maxVel", maxVel);
        this.maxNegVel = ActionArgs.finite(n, "maxNegVel", maxNegVel);
        this.transAccel = ActionArgs.finite(n, "transAccel", transAccel);
        this.transDecel = ActionArgs.finite(n, "transDecel", transDecel);
        this.maxRotVel = ActionArgs.finite(n, "rotVelMax", rotVelMax);
        this.rotAccel = ActionArgs.finite(n, "rotAccel", rotAccel);
        this.rotDecel = ActionArgs.finite(n, "rotDecel", rotDecel);
        this.maxLatVel = ActionArgs.finite(n, "latVelMax", latVelMax);
        this.latAccel = ActionArgs.finite(n, "latAccel", latAccel);
        this.latDecel = ActionArgs.finite(n, "latDecel", latDecel);
    }

    /** @return ARIA's override-faster flag, as given */
    public boolean getOverrideFaster() {
        return overrideFaster;
    }

    /** @return whether the lateral parameters would count on a robot that moves sideways */
    public boolean getAddLatVelIfAvailable() {
        return addLatVelIfAvailable;
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        if (!enabled && !enableOnce) {
            return null;
        }
        enableOnce = false;
        if (Math.abs(maxVel) >= 1) {
            desired.setMaxVel(maxVel);
        }
        if (Math.abs(maxNegVel) >= 1) {
            desired.setMaxNegVel(-maxNegVel);
        }
        if (Math.abs(transAccel) >= 1) {
            desired.setTransAccel(transAccel);
        }
        if (Math.abs(transDecel) >= 1) {
            desired.setTransDecel(transDecel);
        }
        if (Math.abs(maxRotVel) >= 1) {
            desired.setMaxRotVel(maxRotVel);
        }
        if (Math.abs(rotAccel) >= 1) {
            desired.setRotAccel(rotAccel);
        }
        if (Math.abs(rotDecel) >= 1) {
            desired.setRotDecel(rotDecel);
        }
        if (Math.abs(maxLatVel) >= 1) {
            desired.setMaxLeftLatVel(maxLatVel);
            desired.setMaxRightLatVel(maxLatVel);
        }
        if (Math.abs(latAccel) >= 1) {
            desired.setLatAccel(latAccel);
        }
        if (Math.abs(latDecel) >= 1) {
            desired.setLatDecel(latDecel);
        }
        return desired;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
