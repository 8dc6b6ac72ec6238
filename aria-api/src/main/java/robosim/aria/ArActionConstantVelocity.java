package robosim.aria;

/**
 * Drives straight ahead at a constant velocity, as ARIA's ArActionConstantVelocity.cpp: each cycle
 * it wants its velocity and a delta heading of 0, at full strength. The lowest priority of a wander
 * behaviour.
 */
public class ArActionConstantVelocity extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();
    private volatile double velocity;

    /** ARIA's defaults: "Constant Velocity", 400 mm/s. */
    public ArActionConstantVelocity() {
        this("Constant Velocity", 400);
    }

    /** @param name the action's name; 400 mm/s */
    public ArActionConstantVelocity(String name) {
        this(name, 400);
    }

    /**
     * @param name     the action's name
     * @param velocity the velocity to travel at, mm/s
     */
    public ArActionConstantVelocity(String name, double velocity) {
        super(name, "Sets the robot to travel straight at a constant velocity.");
        this.velocity = velocity;
    }

    @Override
    public ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        desired.setVel(velocity);
        desired.setDeltaHeading(0);
        return desired;
    }

    @Override
    public ArActionDesired getDesired() {
        return desired;
    }

    /** @param velocity the velocity to travel at, mm/s */
    public void setVelocity(double velocity) {
        this.velocity = velocity;
    }

    /** @return the velocity it travels at, mm/s */
    public double getVelocity() {
        return velocity;
    }
}
