package robosim.aria;

/**
 * Wandering, as ARIA's {@code ArActionGroupWander} (ArActionGroups.cpp): {@link ArActionBumpers}
 * (100), {@link ArActionStallRecover} (90), an {@link ArActionAvoidFront} "Avoid Front" with the
 * group's distance, speed and turn (79) and an {@link ArActionConstantVelocity} "Constant Velocity"
 * at the forward speed (50). ARIA's defaults: 400 mm/s forward, avoid from 450 mm at 200 mm/s
 * turning 15 degrees. Meant to be used one group at a time ({@link #activateExclusive()}).
 */
public final class ArActionGroupWander extends ArActionGroup {
    /** @param robot the robot its actions are added to; ARIA's defaults */
    public ArActionGroupWander(ArRobot robot) {
        this(robot, 400);
    }

    /** @param robot the robot @param forwardVel the speed it wanders at, mm/s */
    public ArActionGroupWander(ArRobot robot, int forwardVel) {
        this(robot, forwardVel, 450);
    }

    /**
     * @param robot          the robot
     * @param forwardVel     the speed it wanders at, mm/s
     * @param avoidFrontDist the distance it avoids obstacles from, mm
     */
    public ArActionGroupWander(ArRobot robot, int forwardVel, int avoidFrontDist) {
        this(robot, forwardVel, avoidFrontDist, 200);
    }

    /**
     * @param robot          the robot
     * @param forwardVel     the speed it wanders at, mm/s
     * @param avoidFrontDist the distance it avoids obstacles from, mm
     * @param avoidVel       the speed while avoiding, mm/s
     */
    public ArActionGroupWander(ArRobot robot, int forwardVel, int avoidFrontDist, int avoidVel) {
        this(robot, forwardVel, avoidFrontDist, avoidVel, 15);
    }

    /**
     * @param robot          the robot
     * @param forwardVel     the speed it wanders at, mm/s
     * @param avoidFrontDist the distance it avoids obstacles from, mm
     * @param avoidVel       the speed while avoiding, mm/s
     * @param avoidTurnAmt   the turn while avoiding, degrees
     */
    public ArActionGroupWander(ArRobot robot, int forwardVel, int avoidFrontDist, int avoidVel, int avoidTurnAmt) {
        super(robot);
        addAction(new ArActionBumpers(), 100);
        addAction(new ArActionStallRecover(), 90);
        addAction(new ArActionAvoidFront("Avoid Front", avoidFrontDist, avoidVel, avoidTurnAmt), 79);
        addAction(new ArActionConstantVelocity("Constant Velocity", forwardVel), 50);
    }
}
