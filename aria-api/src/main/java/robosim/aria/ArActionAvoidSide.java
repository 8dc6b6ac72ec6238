package robosim.aria;

/**
 * Turns away from obstacles at the sides, as ARIA's ArActionAvoidSide.cpp: the nearest reading
 * between 60° and 120° (left) or −120° and −60° (right), less the robot's radius, nearer than the
 * obstacle distance makes it stop and turn by its turn amount away from that side (left first);
 * once clear it asks for a delta heading of 0.
 */
public class ArActionAvoidSide extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();
    private final double obstacleDistance;
    private final double turnAmount;
    private boolean turning;

    /** ARIA's defaults: "Avoid side", 300 mm, 5°. */
    public ArActionAvoidSide() {
        this("Avoid side", 300, 5);
    }

    /**
     * @param name             the action's name
     * @param obstacleDistance distance at which to start avoiding, mm
     * @param turnAmount       degrees to turn
     */
    public ArActionAvoidSide(String name, double obstacleDistance, double turnAmount) {
        super(name, "Avoids side obstacles, ie walls");
        this.obstacleDistance = obstacleDistance;
        this.turnAmount = turnAmount;
    }

    @Override
    public ArActionDesired fire(ArActionDesired currentDesired) {
        ArRobot robot = getRobot();
        double left = robot.checkRangeDevicesCurrentPolar(60, 120) - robot.getRobotRadius();
        double right = robot.checkRangeDevicesCurrentPolar(-120, -60) - robot.getRobotRadius();
        desired.reset();
        if (left < obstacleDistance) {
            desired.setDeltaHeading(-turnAmount);
            desired.setVel(0);
            turning = true;
        } else if (right < obstacleDistance) {
            desired.setDeltaHeading(turnAmount);
            desired.setVel(0);
            turning = true;
        } else if (turning) {
            desired.setDeltaHeading(0);
        }
        return desired;
    }

    @Override
    public ArActionDesired getDesired() {
        return desired;
    }
}
