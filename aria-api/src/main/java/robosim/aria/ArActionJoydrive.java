package robosim.aria;

/**
 * Drives from the computer's joystick, as ARIA's {@code ArActionJoydrive} (ArActionJoydrive.cpp):
 * with a joystick and its button 1 held, the stick's Y gives the velocity (up to
 * {@code transVelMax}, or scaled between the throttle parameters by the Z axis) and its X a delta
 * heading (up to {@code turnAmountMax}, right turning right); with a joystick and no button held it
 * asks for a stop if {@code stopIfNoButtonPressed}, else nothing.
 *
 * <p><b>In the simulator:</b> there is no joystick ({@link ArJoyHandler} finds none), so
 * {@link #joystickInited()} is false and the action wants nothing, as ARIA's does on a computer
 * without one: lower priorities (such as the keydrive of {@link ArActionGroupTeleop}) drive. ARIA
 * shares one handler through {@code Aria::getJoyHandler}; RoboSim's {@code Aria} has no such slot,
 * so each joydrive makes and initialises its own (or uses the one it is given).
 */
public class ArActionJoydrive extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();
    private final ArJoyHandler joyHandler;
    private double transVelMax;
    private double turnAmountMax;
    private boolean stopIfNoButtonPressed;
    private boolean useOSCal;
    private boolean previousUseOSCal;
    private boolean useThrottle;
    private double lowThrottle;
    private double highThrottle;

    /** ARIA's defaults: "joydrive", 400 mm/s, 15 degrees, stop if no button, the OS's calibration. */
    public ArActionJoydrive() {
        this("joydrive");
    }

    /** @param name the action's name */
    public ArActionJoydrive(String name) {
        this(name, 400);
    }

    /**
     * @param name        the action's name
     * @param transVelMax the speed with the stick all the way forwards or back, mm/s
     */
    public ArActionJoydrive(String name, double transVelMax) {
        this(name, transVelMax, 15);
    }

    /**
     * @param name          the action's name
     * @param transVelMax   the speed with the stick all the way forwards or back, mm/s
     * @param turnAmountMax the turn with the stick all the way left or right, degrees
     */
    public ArActionJoydrive(String name, double transVelMax, double turnAmountMax) {
        this(name, transVelMax, turnAmountMax, true);
    }

    /**
     * @param name                  the action's name
     * @param transVelMax           the speed with the stick all the way forwards or back, mm/s
     * @param turnAmountMax         the turn with the stick all the way left or right, degrees
     * @param stopIfNoButtonPressed whether, with a joystick and no button held, it asks for a stop
     */
    public ArActionJoydrive(String name, double transVelMax, double turnAmountMax, boolean stopIfNoButtonPressed) {
        this(name, transVelMax, turnAmountMax, stopIfNoButtonPressed, true);
    }

    /**
     * @param name                  the action's name
     * @param transVelMax           the speed with the stick all the way forwards or back, mm/s
     * @param turnAmountMax         the turn with the stick all the way left or right, degrees
     * @param stopIfNoButtonPressed whether, with a joystick and no button held, it asks for a stop
     * @param useOSCalForJoystick   whether the joystick uses the operating system's calibration
     */
    public ArActionJoydrive(String name, double transVelMax, double turnAmountMax, boolean stopIfNoButtonPressed,
            boolean useOSCalForJoystick) {
        this(name, transVelMax, turnAmountMax, stopIfNoButtonPressed, useOSCalForJoystick, null);
    }

    /**
     * As the five-argument constructor, reading a given joystick handler (null: its own, initialised).
     *
     * @param name                  the action's name
     * @param transVelMax           the speed with the stick all the way forwards or back, mm/s
     * @param turnAmountMax         the turn with the stick all the way left or right, degrees
     * @param stopIfNoButtonPressed whether, with a joystick and no button held, it asks for a stop
     * @param useOSCalForJoystick   whether the joystick uses the operating system's calibration
     * @param joyHandler            the joystick, or null
     */
    public ArActionJoydrive(String name, double transVelMax, double turnAmountMax, boolean stopIfNoButtonPressed,
            boolean useOSCalForJoystick, ArJoyHandler joyHandler) {
        super(name, "This action reads the joystick and sets the translational and rotational velocities based on"
                + " this.");
        if (joyHandler == null) {
            joyHandler = new ArJoyHandler();
            joyHandler.init();
        }
        this.joyHandler = joyHandler;
        setSpeeds(transVelMax, turnAmountMax);
        setNextArgument(ArArg.ofDouble("trans vel max", () -> this.transVelMax, v -> this.transVelMax = v,
                "The full speed to go when the joystick is maxed forwards/backwards (mm/sec)"));
        setNextArgument(ArArg.ofDouble("turn amount max", () -> this.turnAmountMax, v -> this.turnAmountMax = v,
                "The full amount to turn if the joystick is pushed all the way right/left (deg)"));
        setNextArgument(ArArg.ofBool("stop if no button pressed", () -> this.stopIfNoButtonPressed,
                v -> this.stopIfNoButtonPressed = v,
                "If this is true, then joydrive will stop the robot if there is no button pressed, otherwise it"
                        + " will just let whatever lower priority things are going happen"));
        setNextArgument(ArArg.ofBool("use os calibration for joystick", () -> this.useOSCal, v -> this.useOSCal = v,
                "If this is true then the os calibration for the joystick will be used, otherwise autocalibration"
                        + " will be used"));
        this.stopIfNoButtonPressed = stopIfNoButtonPressed;
        this.useOSCal = useOSCalForJoystick;
        this.previousUseOSCal = useOSCalForJoystick;
    }

    /** @return whether a joystick was found: never in the simulation */
    public boolean joystickInited() {
        return joyHandler.haveJoystick();
    }

    /**
     * @param transVelMax   the speed with the stick all the way forwards or back, mm/s
     * @param turnAmountMax the turn with the stick all the way left or right, degrees
     */
    public synchronized void setSpeeds(double transVelMax, double turnAmountMax) {
        this.transVelMax = ActionArgs.finite(getName(), "transVelMax", transVelMax);
        this.turnAmountMax = ActionArgs.finite(getName(), "turnAmountMax", turnAmountMax);
    }

    /** @param stopIfNoButtonPressed whether, with a joystick and no button held, it asks for a stop */
    public synchronized void setStopIfNoButtonPressed(boolean stopIfNoButtonPressed) {
        this.stopIfNoButtonPressed = stopIfNoButtonPressed;
    }

    /** @return whether, with a joystick and no button held, it asks for a stop */
    public synchronized boolean getStopIfNoButtonPressed() {
        return stopIfNoButtonPressed;
    }

    /**
     * The speed follows the throttle (Z axis), from {@code lowSpeed} to {@code highSpeed}.
     *
     * @param lowSpeed  the speed at the throttle's bottom, mm/s
     * @param highSpeed the speed at its top, mm/s
     */
    public synchronized void setThrottleParams(double lowSpeed, double highSpeed) {
        useThrottle = true;
        lowThrottle = lowSpeed;
        highThrottle = highSpeed;
    }

    /** @param useOSCal whether the joystick uses the operating system's calibration */
    public synchronized void setUseOSCal(boolean useOSCal) {
        this.useOSCal = useOSCal;
        this.previousUseOSCal = useOSCal;
        joyHandler.setUseOSCal(useOSCal);
    }

    /** @return whether the joystick uses the operating system's calibration */
    public synchronized boolean getUseOSCal() {
        return useOSCal;
    }

    /** @return the joystick it reads */
    public ArJoyHandler getJoyHandler() {
        return joyHandler;
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        if (previousUseOSCal != useOSCal) {
            joyHandler.setUseOSCal(useOSCal);
            previousUseOSCal = useOSCal;
        }
        if (joyHandler.haveJoystick() && joyHandler.getButton(1)) {
            double[] x = new double[1];
            double[] y = new double[1];
            joyHandler.getDoubles(x, y);
            double rot = x[0] * turnAmountMax;
            double trans;
            if (!useThrottle || !joyHandler.haveZAxis()) {
                trans = y[0] * transVelMax;
            } else {
                double throttle = (joyHandler.getAxis(3) + 1.0) / 2.0;
                trans = y[0] * (lowThrottle + throttle * (highThrottle - lowThrottle));
            }
            desired.setVel(trans);
            desired.setDeltaHeading(-rot);
            return desired;
        }
        if (joyHandler.haveJoystick() && stopIfNoButtonPressed) {
            desired.setVel(0);
            desired.setDeltaHeading(0);
            return desired;
        }
        return null;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
