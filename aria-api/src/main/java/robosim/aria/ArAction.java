package robosim.aria;

/**
 * A behaviour that says each cycle what motion it wants, as ARIA's {@code ArAction} (ArAction.cpp):
 * the robot's resolver calls {@link #fire} on every active action, highest priority first, and
 * combines what they return (see {@link ArPriorityResolver}).
 *
 * <p>Actions run in the robot's cycle, under the robot's lock, after the sensor-interpretation
 * tasks and before the user tasks, as in ARIA's task order; {@code fire} must not sleep. Actions
 * drive the robot only while no direct motion command holds it (see
 * {@link ArRobot#setDirectMotionPrecedenceTime}).
 *
 * <pre>{@code
 * class Forward extends ArAction {
 *     private final ArActionDesired desired = new ArActionDesired();
 *     Forward() { super("forward"); }
 *     public ArActionDesired fire(ArActionDesired current) {
 *         desired.reset();
 *         desired.setVel(300);
 *         return desired;
 *     }
 * }
 * robot.addAction(new Forward(), 50);
 * }</pre>
 */
public abstract class ArAction {
    private static volatile boolean defaultActivationState = true;

    private final String name;
    private final String description;
    private volatile boolean active;
    /** The robot the action was added to, or null: ARIA's {@code myRobot}, for actions ported from C++. */
    protected volatile ArRobot myRobot;
    private final java.util.List<ArArg> args = new java.util.concurrent.CopyOnWriteArrayList<>();

    /** @param name the action's name, as {@link ArRobot#findAction} finds it */
    protected ArAction(String name) {
        this(name, "");
    }

    /**
     * @param name        the action's name
     * @param description what it does
     */
    protected ArAction(String name, String description) {
        this.name = name;
        this.description = description == null ? "" : description;
        this.active = defaultActivationState;
    }

    /**
     * Says what this action wants this cycle.
     *
     * @param currentDesired what the actions of higher priority want, combined (a copy)
     * @return what this action wants, or null for nothing
     */
    public abstract ArActionDesired fire(ArActionDesired currentDesired);

    /** @return the action's name */
    public String getName() {
        return name;
    }

    /** @return what the action does */
    public String getDescription() {
        return description;
    }

    /** @return whether the resolver fires this action */
    public boolean isActive() {
        return active;
    }

    /** The resolver fires this action from the next cycle on. */
    public void activate() {
        active = true;
    }

    /** The resolver skips this action from the next cycle on. */
    public void deactivate() {
        active = false;
    }

    /**
     * Called when the action is added to a robot (or removed, with null).
     *
     * @param robot the robot, or null
     */
    public void setRobot(ArRobot robot) {
        this.myRobot = robot;
    }

    /** @return the robot the action was added to, or null */
    public ArRobot getRobot() {
        return myRobot;
    }

    /**
     * Adds a parameter others may find and set, as ARIA's {@code setNextArgument}.
     *
     * @param arg the parameter
     */
    protected void setNextArgument(ArArg arg) {
        args.add(arg);
    }

    /** @return how many parameters the action gave */
    public int getNumArgs() {
        return args.size();
    }

    /**
     * @param number a parameter's number, from 0
     * @return it, or null
     */
    public ArArg getArg(int number) {
        return number >= 0 && number < args.size() ? args.get(number) : null;
    }

    /** Logs the action's name, description and parameters, as ARIA's {@code ArAction::log}. */
    public void log() {
        ArLog.log(ArLog.Terse, "Action %s isActive %b", name, active);
        if (!description.isEmpty()) {
            ArLog.log(ArLog.Terse, "Action description:\n%s", description);
        }
        if (!args.isEmpty()) {
            ArLog.log(ArLog.Terse, "Parameters:");
            for (int i = 0; i < args.size(); i++) {
                ArLog.log(ArLog.Terse, "Parameter #%d:", i);
                args.get(i).log();
            }
        }
    }

    /** @return what the action wanted at its last firing, or null if it keeps none */
    public ArActionDesired getDesired() {
        return null;
    }

    /**
     * @param activeByDefault whether actions made from now on start active (ARIA's default: true)
     */
    public static void setDefaultActivationState(boolean activeByDefault) {
        defaultActivationState = activeByDefault;
    }

    /** @return whether actions start active */
    public static boolean getDefaultActivationState() {
        return defaultActivationState;
    }

    @Override
    public String toString() {
        return "action '" + name + "'" + (active ? "" : " (inactive)");
    }
}
