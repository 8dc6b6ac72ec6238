package robosim.aria;

/**
 * Gets the robot out of a stall, as ARIA's ArActionStallRecover.cpp: when a motor stalls and no
 * higher-priority action holds the robot at full strength, it runs one manoeuvre of its sequence
 * (back and turn away, forward and turn, back, forward, turn left, turn right, back and left, back
 * and right, forward and left, forward and right) for at most the cycles to move; a stall again
 * within 5 simulated seconds of its last firing takes the next manoeuvre, a later one starts the
 * sequence again. Moving, it stops early past half its cycles when something is nearer than the
 * obstacle distance; turning, it ends within 3° of its heading. "Turn away" turns towards the side
 * whose nearest reading is farther (or away from the stalled wheel).
 */
public class ArActionStallRecover extends ArAction {
    private static final int BACK = 0x1;
    private static final int FORWARD = 0x2;
    private static final int TURN = 0x4;
    private static final int TURN_LEFT = 0x8;
    private static final int TURN_RIGHT = 0x10;
    private static final int MOVEMASK = BACK | FORWARD;
    private static final int TURNMASK = TURN | TURN_LEFT | TURN_RIGHT;
    private static final int[] SEQUENCE = {BACK | TURN, FORWARD | TURN, BACK, FORWARD, TURN_LEFT, TURN_RIGHT,
        BACK | TURN_LEFT, BACK | TURN_RIGHT, FORWARD | TURN_LEFT, FORWARD | TURN_RIGHT};

    private final ArActionDesired desired = new ArActionDesired();
    private final double obstacleDistance;
    private final int cyclesToMove;
    private final double speed;
    private final double degreesToTurn;
    private final boolean enabled;
    private boolean going;
    private int count = -1;
    private int sequencePos;
    private long lastFiredSec = Long.MIN_VALUE / 2;
    private int doing;
    private double desiredHeading;

    /** ARIA's defaults: "stall recover", 225 mm, 50 cycles, 150 mm/s, 45°, enabled. */
    public ArActionStallRecover() {
        this("stall recover", 225, 50, 150, 45, true);
    }

    /** @param name the action's name; ARIA's other defaults */
    public ArActionStallRecover(String name) {
        this(name, 225, 50, 150, 45, true);
    }

    /** @param name the action's name @param obstacleDistance distance at which not to move, mm */
    public ArActionStallRecover(String name, double obstacleDistance) {
        this(name, obstacleDistance, 50, 150, 45, true);
    }

    /**
     * @param name             the action's name
     * @param obstacleDistance distance at which not to move, mm
     * @param cyclesToMove     cycles a manoeuvre lasts at most
     */
    public ArActionStallRecover(String name, double obstacleDistance, int cyclesToMove) {
        this(name, obstacleDistance, cyclesToMove, 150, 45, true);
    }

    /**
     * @param name             the action's name
     * @param obstacleDistance distance at which not to move, mm
     * @param cyclesToMove     cycles a manoeuvre lasts at most
     * @param speed            speed to back up or go forward at, mm/s
     */
    public ArActionStallRecover(String name, double obstacleDistance, int cyclesToMove, double speed) {
        this(name, obstacleDistance, cyclesToMove, speed, 45, true);
    }

    /**
     * @param name             the action's name
     * @param obstacleDistance distance at which not to move, mm
     * @param cyclesToMove     cycles a manoeuvre lasts at most
     * @param speed            speed to back up or go forward at, mm/s
     * @param degreesToTurn    degrees to turn
     */
    public ArActionStallRecover(String name, double obstacleDistance, int cyclesToMove, double speed,
                                double degreesToTurn) {
        this(name, obstacleDistance, cyclesToMove, speed, degreesToTurn, true);
    }

    /**
     * @param name             the action's name
     * @param obstacleDistance distance at which not to move because of an obstacle, mm
     * @param cyclesToMove     cycles a manoeuvre lasts at most
     * @param speed            speed to back up or go forward at, mm/s
     * @param degreesToTurn    degrees to turn
     * @param enabled          whether it acts at all
     */
    public ArActionStallRecover(String name, double obstacleDistance, int cyclesToMove, double speed,
                                double degreesToTurn, boolean enabled) {
        super(name, "Recovers the robot from a stall.");
        this.obstacleDistance = obstacleDistance;
        this.cyclesToMove = cyclesToMove;
        this.speed = speed;
        this.degreesToTurn = degreesToTurn;
        this.enabled = enabled;
    }

    @Override
    public void activate() {
        going = false;
        super.activate();
    }

    @Override
    public ArActionDesired fire(ArActionDesired currentDesired) {
        if (!enabled) {
            return null;
        }
        ArRobot robot = getRobot();
        if (currentDesired.getVelStrength() >= 1.0 || currentDesired.getDeltaHeadingStrength() >= 1.0
                || currentDesired.getHeadingStrength() >= 1.0 || currentDesired.getRotVelStrength() >= 1.0) {
            if (going) {
                going = false;
                count = -1;
            }
            return null;
        }
        desired.reset();
        long nowSec = robot.getSimTimeMs() / 1000;
        if (!going) {
            if (!robot.isLeftMotorStalled() && !robot.isRightMotorStalled()) {
                return null;
            }
            sequencePos = nowSec - lastFiredSec <= 5 ? sequencePos + 1 : 0;
            if (sequencePos >= SEQUENCE.length) {
                sequencePos = 0;
            }
            doing = SEQUENCE[sequencePos];
            desired.setVel(0);
            desired.setDeltaHeading(0);
        }
        lastFiredSec = nowSec;
        doit(robot);
        return desired;
    }

    private void doit(ArRobot robot) {
        if (count == -1 || !going) {
            count = cyclesToMove;
            going = true;
            int sideStalled = (robot.isLeftMotorStalled() ? 1 : 0) + (robot.isRightMotorStalled() ? 2 : 0);
            if ((doing & TURN) != 0) {
                double right = robot.checkRangeDevicesCurrentPolar(-120, -60);
                double left = robot.checkRangeDevicesCurrentPolar(60, 120);
                int direction;
                if (sideStalled == 1 || right < 0) {
                    direction = -1;
                } else if (sideStalled == 2 || left < 0) {
                    direction = 1;
                } else {
                    direction = right < left ? 1 : -1;
                }
                desiredHeading = robot.getTh() + direction * degreesToTurn;
            } else if ((doing & TURN_LEFT) != 0) {
                desiredHeading = robot.getTh() + degreesToTurn;
            } else if ((doing & TURN_RIGHT) != 0) {
                desiredHeading = robot.getTh() - degreesToTurn;
            }
        } else {
            count--;
        }
        boolean transFired = false;
        if ((doing & MOVEMASK) != 0) {
            if ((doing & TURNMASK) == 0) {
                desired.setRotVel(0);
            }
            double dist = 0;
            if ((doing & FORWARD) != 0) {
                dist = robot.checkRangeDevicesCurrentPolar(-120, 120) - robot.getRobotRadius();
            } else if ((doing & BACK) != 0) {
                dist = robot.checkRangeDevicesCurrentPolar(120, -120) - robot.getRobotRadius();
            }
            if (count <= 0 || (dist > 0 && dist < obstacleDistance && count <= cyclesToMove / 2)) {
                desired.setVel(0);
            } else {
                desired.setVel((doing & BACK) != 0 ? -speed : speed);
                transFired = true;
            }
        }
        boolean rotFired = false;
        if ((doing & TURNMASK) != 0) {
            if ((doing & MOVEMASK) == 0) {
                desired.setVel(0);
            }
            if (count <= 0 || degreesToTurn == 0 || Math.abs(ArMath.subAngle(robot.getTh(), desiredHeading)) < 3) {
                desired.setRotVel(0);
            } else {
                desired.setHeading(desiredHeading);
                rotFired = true;
            }
        }
        if (count <= 0 || (!transFired && !rotFired)) {
            going = false;
            desired.reset();
        }
    }

    @Override
    public ArActionDesired getDesired() {
        return desired;
    }
}
