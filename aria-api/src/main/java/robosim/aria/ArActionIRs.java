package robosim.aria;

/**
 * Backs away and turns when the robot's infrared sensors trigger, as ARIA's {@code ArActionIRs}
 * (ArActionIRs.cpp): ARIA reads the table-sensing IRs of a robot whose parameter file lists them
 * ({@code TableSensingIR}, {@code NumIR}), and when forward IRs have triggered for their cycles while
 * it drives faster than 50 mm/s, it e-stops, backs off at {@code backOffSpeed} for
 * {@code backOffTime}, turns away for up to {@code turnTime} and stays stopped a second.
 *
 * <p><b>In the simulator:</b> the simulated Pioneers have no IR sensors (their parameter files'
 * {@code TableSensingIR} is not simulated), so this takes ARIA's path for a robot without table
 * sensing IRs: it never starts backing off and {@link #fire} returns null, every cycle. The
 * parameters are kept, and listed as ARIA lists them.
 */
public class ArActionIRs extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();
    private double backOffSpeed;
    private int backOffTime;
    private int turnTime;
    private boolean setMaximums;

    /** ARIA's defaults: "IRs", 100 mm/s for 5000 ms, 3000 ms to turn, no maximums. */
    public ArActionIRs() {
        this("IRs");
    }

    /** @param name the action's name */
    public ArActionIRs(String name) {
        this(name, 100);
    }

    /**
     * @param name         the action's name
     * @param backOffSpeed the speed it backs away at, mm/s
     */
    public ArActionIRs(String name, double backOffSpeed) {
        this(name, backOffSpeed, 5000);
    }

    /**
     * @param name         the action's name
     * @param backOffSpeed the speed it backs away at, mm/s
     * @param backOffTime  how long it backs away, ms
     */
    public ArActionIRs(String name, double backOffSpeed, int backOffTime) {
        this(name, backOffSpeed, backOffTime, 3000);
    }

    /**
     * @param name         the action's name
     * @param backOffSpeed the speed it backs away at, mm/s
     * @param backOffTime  how long it backs away, ms
     * @param turnTime     how long it may turn, ms
     */
    public ArActionIRs(String name, double backOffSpeed, int backOffTime, int turnTime) {
        this(name, backOffSpeed, backOffTime, turnTime, false);
    }

    /**
     * @param name         the action's name
     * @param backOffSpeed the speed it backs away at, mm/s
     * @param backOffTime  how long it backs away, ms
     * @param turnTime     how long it may turn, ms
     * @param setMaximums  whether it would also set maximum velocities
     */
    public ArActionIRs(String name, double backOffSpeed, int backOffTime, int turnTime, boolean setMaximums) {
        super(name, "Reacts to the IRs triggering");
        this.backOffSpeed = backOffSpeed;
        this.backOffTime = backOffTime;
        this.turnTime = turnTime;
        this.setMaximums = setMaximums;
        setNextArgument(ArArg.ofDouble("back off speed", () -> this.backOffSpeed, v -> this.backOffSpeed = v,
                "Speed at which to back away (mm/sec)"));
        setNextArgument(ArArg.ofInt("back off time", () -> this.backOffTime, v -> this.backOffTime = v,
                "Number of msec to back up for (msec)"));
        setNextArgument(ArArg.ofInt("turn time", () -> this.turnTime, v -> this.turnTime = v,
                "Number of msec to allow for turn (msec)"));
        setNextArgument(ArArg.ofBool("set maximums", () -> this.setMaximums, v -> this.setMaximums = v,
                "Whether to set maximum vels or not (bool)"));
    }

    /** @return whether the robot has IRs this action reads: no simulated robot has */
    public boolean haveTableSensingIR() {
        return false;
    }

    /**
     * As ARIA's on a robot without table-sensing IRs: it is never backing off (ARIA's back-off,
     * turn and stop all start from a triggered IR), and with no IRs to read it returns nothing,
     * every cycle.
     */
    @Override
    public ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        return null;
    }

    @Override
    public ArActionDesired getDesired() {
        return desired;
    }
}
