package robosim.aria;

/**
 * Limits turning while something is within the robot's radius, as ARIA's
 * {@code ArActionLimiterRot} (ArActionLimiterRot.cpp): when {@code checkRadius} is set, the closest
 * current reading of the robot's range devices to the left (0 to 180 degrees) and to the right (-180
 * to 0), nearer than the robot's radius from its centre, asks for a maximum rotational velocity of
 * {@code inRadiusSpeed} (0 or less: no rotation at all); otherwise, and by default, nothing.
 *
 * <p>ARIA's location-dependent devices (the map-based ones) do not exist in RoboSim; the flag is
 * kept, and every range device of the robot is read either way.
 */
public class ArActionLimiterRot extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();
    private boolean checkRadius;
    private double inRadiusSpeed;
    private boolean useLocationDependentDevices = true;

    /** ARIA's default name, "limitRot"; not checking the radius. */
    public ArActionLimiterRot() {
        this("limitRot");
    }

    /** @param name the action's name */
    public ArActionLimiterRot(String name) {
        super(name, "Applies a limit to rotation if there are sensor readings in the radius");
        setParameters();
    }

    /** ARIA's defaults: not checking the radius. */
    public void setParameters() {
        setParameters(false);
    }

    /** @param checkRadius whether it checks the radius (with an in-radius speed of 0) */
    public void setParameters(boolean checkRadius) {
        setParameters(checkRadius, 0);
    }

    /**
     * @param checkRadius   whether it checks the radius
     * @param inRadiusSpeed the largest rotational velocity while something is within the radius,
     *                      deg/s; 0 or less for none
     */
    public synchronized void setParameters(boolean checkRadius, double inRadiusSpeed) {
        this.checkRadius = checkRadius;
        this.inRadiusSpeed = ActionArgs.finite(getName(), "inRadiusSpeed", inRadiusSpeed);
    }

    /** @return whether location-dependent devices would be read (no effect in RoboSim) */
    public synchronized boolean getUseLocationDependentDevices() {
        return useLocationDependentDevices;
    }

    /** @param use whether location-dependent devices would be read (no effect in RoboSim) */
    public synchronized void setUseLocationDependentDevices(boolean use) {
        useLocationDependentDevices = use;
    }

    @Override
    public synchronized ArActionDesired fire(ArActionDesired currentDesired) {
        if (!checkRadius) {
            return null;
        }
        desired.reset();
        double leftDist = myRobot.checkRangeDevicesCurrentPolar(0, 179.999);
        double rightDist = myRobot.checkRangeDevicesCurrentPolar(-179.999, 0);
        double dist;
        if (leftDist > 0 && rightDist < 0) {
            dist = leftDist;
        } else if (rightDist > 0 && leftDist < 0) {
            dist = rightDist;
        } else if (leftDist > 0 && rightDist > 0) {
            dist = Math.min(leftDist, rightDist);
        } else {
            dist = -1;
        }
        if (dist > 0 && dist < myRobot.getRobotRadius()) {
            desired.setMaxRotVel(inRadiusSpeed <= 0 ? 0 : inRadiusSpeed);
            return desired;
        }
        return null;
    }

    @Override
    public synchronized ArActionDesired getDesired() {
        return desired;
    }
}
