package robosim.aria;

/**
 * Slows down and turns away from obstacles ahead, as ARIA's ArActionAvoidFront.cpp: it looks for
 * the nearest range reading between −70° and 70° (over the robot's range devices, less the robot's
 * radius). Nearer than the obstacle distance it turns by its turn amount, away from the side the
 * reading is on, keeping that direction until the way is clear; it drives at the avoid velocity
 * scaled by distance / obstacle distance, and not at all nearer than half the obstacle distance. If
 * the robot turns through all eight 45° sectors without getting clear, the turn amount is halved.
 * When the way is clear again it asks once for a delta heading of 0, then for nothing.
 *
 * <p>RoboSim's robots have no table-sensing IR: the {@code useTableIRIfAvail} argument is accepted
 * for ARIA's signature and changes nothing.
 */
public class ArActionAvoidFront extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();
    private final Sectors quadrants = new Sectors(8);
    private final double obstacleDistance;
    private final double avoidVelocity;
    private final double turnAmountParam;
    private double turnAmount;
    private int turning;

    /** ARIA's defaults: "avoid front obstacles", 450 mm, 200 mm/s, 15°. */
    public ArActionAvoidFront() {
        this("avoid front obstacles", 450, 200, 15);
    }

    /** @param name the action's name; the rest ARIA's defaults (450 mm, 200 mm/s, 15°), as C++'s default arguments */
    public ArActionAvoidFront(String name) {
        this(name, 450, 200, 15);
    }

    /** @param name the action's name @param obstacleDistance distance at which to turn, mm; 200 mm/s, 15° */
    public ArActionAvoidFront(String name, double obstacleDistance) {
        this(name, obstacleDistance, 200, 15);
    }

    /**
     * @param name             the action's name
     * @param obstacleDistance distance at which to turn, mm
     * @param avoidVelocity    speed while avoiding, mm/s; it turns 15°
     */
    public ArActionAvoidFront(String name, double obstacleDistance, double avoidVelocity) {
        this(name, obstacleDistance, avoidVelocity, 15);
    }

    /**
     * @param name             the action's name
     * @param obstacleDistance distance at which to turn, mm
     * @param avoidVelocity    speed while avoiding, mm/s
     * @param turnAmount       degrees to turn from the current heading while avoiding
     */
    public ArActionAvoidFront(String name, double obstacleDistance, double avoidVelocity, double turnAmount) {
        super(name, "Slows down and avoids obstacles in front of the robot.");
        this.obstacleDistance = obstacleDistance;
        this.avoidVelocity = avoidVelocity;
        this.turnAmountParam = turnAmount;
    }

    /**
     * ARIA's full signature.
     *
     * @param name              the action's name
     * @param obstacleDistance  distance at which to turn, mm
     * @param avoidVelocity     speed while avoiding, mm/s
     * @param turnAmount        degrees to turn while avoiding
     * @param useTableIRIfAvail ignored: RoboSim's robots have no table-sensing IR
     */
    public ArActionAvoidFront(String name, double obstacleDistance, double avoidVelocity, double turnAmount,
                              boolean useTableIRIfAvail) {
        this(name, obstacleDistance, avoidVelocity, turnAmount);
    }

    @Override
    public ArActionDesired fire(ArActionDesired currentDesired) {
        ArRobot robot = getRobot();
        if (currentDesired.getDeltaHeadingStrength() >= 1.0) {
            turning = 0;
        }
        desired.reset();
        double[] angle = new double[1];
        double dist = robot.checkRangeDevicesCurrentPolar(-70, 70, angle) - robot.getRobotRadius();
        if (dist > obstacleDistance) {
            if (turning != 0) {
                desired.setDeltaHeading(0);
                turning = 0;
                return desired;
            }
            return null;
        }
        if (turning == 0) {
            turning = angle[0] < 0 ? 1 : -1;
            turnAmount = turnAmountParam;
            quadrants.clear();
        }
        quadrants.update(robot.getTh());
        if (quadrants.didAll()) {
            quadrants.clear();
            turnAmount /= 2;
            if (turnAmount == 0) {
                turnAmount = turnAmountParam;
            }
        }
        desired.setDeltaHeading(turning * turnAmount);
        desired.setVel(dist > obstacleDistance / 2 ? avoidVelocity * dist / obstacleDistance : 0);
        return desired;
    }

    @Override
    public ArActionDesired getDesired() {
        return desired;
    }
}
