package robosim.aria;

/**
 * Stops the robot when its table-sensing IRs see a table edge ahead, as ARIA's
 * {@code ArActionLimiterTableSensor} (ArActionLimiterTableSensor.cpp): if the robot has table
 * sensors and the left or right one is triggered, a maximum velocity of 0; else nothing.
 *
 * <p><b>In the simulator:</b> no simulated robot has table-sensing IRs, so it takes ARIA's path for
 * a robot without them: {@link #fire} returns null every cycle. It is kept so that ARIA's groups
 * ({@link ArActionGroupInput}, {@link ArActionGroupTeleop}) hold the same actions as ARIA's.
 */
public class ArActionLimiterTableSensor extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();

    /** ARIA's default name, "TableSensorLimiter". */
    public ArActionLimiterTableSensor() {
        this("TableSensorLimiter");
    }

    /** @param name the action's name */
    public ArActionLimiterTableSensor(String name) {
        super(name, "Limits speed to 0 if a table is seen");
    }

    @Override
    public ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        // ARIA: robot->hasTableSensingIR() && (left || right triggered) -> setMaxVel(0).
        // No simulated robot has table-sensing IRs.
        return null;
    }

    @Override
    public ArActionDesired getDesired() {
        return desired;
    }
}
