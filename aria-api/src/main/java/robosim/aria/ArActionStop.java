package robosim.aria;

/**
 * Holds the robot still, as ARIA's ArActionStop.cpp: a velocity of 0 and a delta heading of 0 at
 * full strength. Activated above other actions (or exclusively, in a group) it stops the robot
 * without taking motion from the actions as {@link ArRobot#stop()} does.
 */
public class ArActionStop extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();

    /** ARIA's default name, "stop". */
    public ArActionStop() {
        this("stop");
    }

    /** @param name the action's name */
    public ArActionStop(String name) {
        super(name, "Stops the robot");
    }

    @Override
    public ArActionDesired fire(ArActionDesired currentDesired) {
        desired.reset();
        desired.setVel(0);
        desired.setDeltaHeading(0);
        return desired;
    }

    @Override
    public ArActionDesired getDesired() {
        return desired;
    }
}
