package robosim.aria;

/**
 * Sets chosen maximum velocities and accelerations, for debugging, as ARIA's
 * {@code ArActionMovementParametersDebugging} (ArActionMovementParametersDebugging.cpp): each limit
 * has a flag and a value, and each flagged one is asked for at full strength, value as given (the
 * backward maximum too: give it negative, as the desire wants; ARIA's default 1000 would be clamped
 * to 0 by the sanity check). By default no flag is set, so it asks for nothing (but answers a
 * desire). Disabled, it wants nothing, except for one firing after {@link #enableOnceFromSector}.
 *
 * <p>ARIA sets the flags and values through {@code addToConfig}, which RoboSim leaves out; they
 * are the action's parameters ({@link #getArg}, ARIA's config names: "SetTransVelMax",
 * "TransVelMax", ...) and its setters ({@link #setMaxVel(boolean, double)}, ...). The lateral ones go
 * to the desire's lateral channels, which no simulated robot uses.
 */
public class ArActionMovementParametersDebugging extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();
    private boolean enabled = true;
    private boolean enableOnce;
    private boolean setMaxVel;
    private double maxVel = 2000;
    private boolean setMaxNegVel;
    private double maxNegVel = 1000;
    private boolean setTransAccel;
    private double transAccel = 500;
    private boolean setTransDecel;
    private double transDecel = 500;
    private boolean setMaxRotVel;
    private double maxRotVel = 250;
    private boolean setRotAccel;
    private double rotAccel = 250;
    private boolean setRotDecel;
    private double rotDecel = 250;
    private boolean setMaxLeftLatVel;
    private double maxLeftLatVel = 2000;
    private boolean setMaxRightLatVel;
    private double maxRightLatVel = 2000;
    private boolean setLatAccel;
    private double latAccel = 500;
    private boolean setLatDecel;
    private double latDecel = 500;

    /** ARIA's default name, "MovementParametersDebugging". */
    public ArActionMovementParametersDebugging() {
        this("MovementParametersDebugging");
    }

    /** @param name the action's name */
    public ArActionMovementParametersDebugging(String name) {
        super(name, "Sets all the max vel and accels/decels in a way appropriate for debugging");
        setNextArgument(ArArg.ofBool("SetTransVelMax", () -> setMaxVel, v -> setMaxVel = v,
                "True to set the transVelMax"));
        setNextArgument(ArArg.ofDouble("TransVelMax", () -> maxVel, v -> maxVel = v,
                "Maximum forward translational velocity"));
        setNextArgument(ArArg.ofBool("SetTransNegVelMax", () -> setMaxNegVel, v -> setMaxNegVel = v,
                "True to set the transNegVelMax"));
        setNextArgument(ArArg.ofDouble("TransNegVelMax", () -> maxNegVel, v -> maxNegVel = v,
                "Maximum backwards translational velocity"));
        setNextArgument(ArArg.ofBool("SetTransAccel", () -> setTransAccel, v -> setTransAccel = v,
                "True to set the transAccel"));
        setNextArgument(ArArg.ofDouble("TransAccel", () -> transAccel, v -> transAccel = v,
                "Translational acceleration"));
        setNextArgument(ArArg.ofBool("SetTransDecel", () -> setTransDecel, v -> setTransDecel = v,
                "True to set the transDecel"));
        setNextArgument(ArArg.ofDouble("TransDecel", () -> transDecel, v -> transDecel = v,
                "Translational deceleration"));
        setNextArgument(ArArg.ofBool("SetRotVelMax", () -> setMaxRotVel, v -> setMaxRotVel = v,
                "True to set the rotVelMax"));
        setNextArgument(ArArg.ofDouble("RotVelMax", () -> maxRotVel, v -> maxRotVel = v,
                "Maximum rotational velocity"));
        setNextArgument(ArArg.ofBool("SetRotAccel", () -> setRotAccel, v -> setRotAccel = v,
                "True to set the rotAccel"));
        setNextArgument(ArArg.ofDouble("RotAccel", () -> rotAccel, v -> rotAccel = v, "Rotational acceleration"));
        setNextArgument(ArArg.ofBool("SetRotDecel", () -> setRotDecel, v -> setRotDecel = v,
                "True to set the rotDecel"));
        setNextArgument(ArArg.ofDouble("RotDecel", () -> rotDecel, v -> rotDecel = v, "Rotational deceleration"));
        setNextArgument(ArArg.ofBool("SetLeftLatVelMax", () -> setMaxLeftLatVel, v -> setMaxLeftLatVel = v,
                "True to set the leftLatVelMax"));
        setNextArgument(ArArg.ofDouble("LeftLatVelMax", () -> maxLeftLatVel, v -> maxLeftLatVel = v,
                "Maximum left lateral velocity"));
        setNextArgument(ArArg.ofBool("SetRightLatVelMax", () -> setMaxRightLatVel, v -> setMaxRightLatVel = v,
                "True to set the rightLatVelMax"));
        setNextArgument(ArArg.ofDouble("RightLatVelMax", () -> maxRightLatVel, v -> maxRightLatVel = v,
                "Maximum right lateral velocity"));
        setNextArgument(ArArg.ofBool("SetLatAccel", () -> setLatAccel, v -> setLatAccel = v,
                "True to set the latAccel"));
        setNextArgument(ArArg.ofDouble("LatAccel", () -> latAccel, v -> latAccel = v, "Lateral acceleration"));
        setNextArgument(ArArg.ofBool("SetLatDecel", () -> setLatDecel, v -> setLatDecel = v,
                "True to set the latDecel"));
        setNextArgument(ArArg.ofDouble("LatDecel", () -> latDecel, v -> latDecel = v, "Lateral deceleration"));
    }

    /** @return whether it fires */
    public synchronized boolean isEnabled() {
        return enabled;
    }

    /** It asks for its limits from now on. */
    public synchronized void enable() {
        enabled = true;
    }

    /** It asks for its limits at the next firing only, though disabled. */
    public synchronized void enableOnceFromSector() {
        enableOnce = true;
    }

    /** @param mapObject ignored, as ARIA's */
    public void enableOnceFromSector(Object mapObject) {
        enableOnceFromSector();
    }

    /** It wants nothing from now on. */
    public synchronized void disable() {
        enabled = false;
    }

    /**
     * @param set   whether it asks for the maximum forward translational velocity
     * @param value the maximum forward translational velocity, mm/s (ARIA's default 2000)
     */
    public synchronized void setMaxVel(boolean set, double value) {
        setMaxVel = set;
        maxVel = value;
    }

    /**
     * @param set   whether it asks for the maximum backwards translational velocity
     * @param value the maximum backwards translational velocity, mm/s (ARIA's default 1000)
     */
    public synchronized void setMaxNegVel(boolean set, double value) {
        setMaxNegVel = set;
        maxNegVel = value;
    }

    /**
     * @param set   whether it asks for the translational acceleration
     * @param value the translational acceleration, mm/s² (ARIA's default 500)
     */
    public synchronized void setTransAccel(boolean set, double value) {
        setTransAccel = set;
        transAccel = value;
    }

    /**
     * @param set   whether it asks for the translational deceleration
     * @param value the translational deceleration, mm/s² (ARIA's default 500)
     */
    public synchronized void setTransDecel(boolean set, double value) {
        setTransDecel = set;
        transDecel = value;
    }

    /**
     * @param set   whether it asks for the maximum rotational velocity
     * @param value the maximum rotational velocity, deg/s (ARIA's default 250)
     */
    public synchronized void setMaxRotVel(boolean set, double value) {
        setMaxRotVel = set;
        maxRotVel = value;
    }

    /**
     * @param set   whether it asks for the rotational acceleration
     * @param value the rotational acceleration, deg/s² (ARIA's default 250)
     */
    public synchronized void setRotAccel(boolean set, double value) {
        setRotAccel = set;
        rotAccel = value;
    }

    /**
     * @param set   whether it asks for the rotational deceleration
     * @param value the rotational deceleration, deg/s² (ARIA's default 250)
     */
    public synchronized void setRotDecel(boolean set, double value) {
        setRotDecel = set;
        rotDecel = value;
    }

    /**
     * @param set   whether it asks for the maximum left lateral velocity
     * @param value the maximum left lateral velocity, mm/s (ARIA's default 2000)
     */
    public synchronized void setMaxLeftLatVel(boolean set, double value) {
        setMaxLeftLatVel = set;
        maxLeftLatVel = value;
    }

    /**
     * @param set   whether it asks for the maximum right lateral velocity
     * @param value the maximum right lateral velocity, mm/s (ARIA's default 2000)
     */
    public synchronized void setMaxRightLatVel(boolean set, double value) {
        setMaxRightLatVel = set;
        maxRightLatVel = value;
    }

    /**
     * @param set   whether it asks for the lateral acceleration
     * @param value the lateral acceleration, mm/s² (ARIA's default 500)
     */
    public synchronized void setLatAccel(boolean set, double value) {
        setLatAccel = set;
        latAccel = value;
    }

    /**
     * @param set   whether it asks for the lateral deceleration
     * @param value the lateral deceleration, mm/s² (ARIA's default 500)
     */
    public synchronized void setLatDecel(boolean set, double value) {
        setLatDecel = set;
        latDecel = value;
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        if (!enabled && !enableOnce) {
            return null;
        }
        enableOnce = false;
        if (setMaxVel) {
            desired.setMaxVel(maxVel);
        }
        if (setMaxNegVel) {
            desired.setMaxNegVel(maxNegVel);
        }
        if (setTransAccel) {
            desired.setTransAccel(transAccel);
        }
        if (setTransDecel) {
            desired.setTransDecel(transDecel);
        }
        if (setMaxRotVel) {
            desired.setMaxRotVel(maxRotVel);
        }
        if (setRotAccel) {
            desired.setRotAccel(rotAccel);
        }
        if (setRotDecel) {
            desired.setRotDecel(rotDecel);
        }
        if (setMaxLeftLatVel) {
            desired.setMaxLeftLatVel(maxLeftLatVel);
        }
        if (setMaxRightLatVel) {
            desired.setMaxRightLatVel(maxRightLatVel);
        }
        if (setLatAccel) {
            desired.setLatAccel(latAccel);
        }
        if (setLatDecel) {
            desired.setLatDecel(latDecel);
        }
        return desired;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
