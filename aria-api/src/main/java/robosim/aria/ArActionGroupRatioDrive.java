package robosim.aria;

/**
 * Teleoperation through ratios, guarded, as ARIA's {@code ArActionGroupRatioDrive}
 * (ArActionGroups.cpp), ARIA's recommended teleoperation group: an {@link ArActionRatioInput} (50)
 * fed by an {@link ArRatioInputKeydrive} (the arrow keys of the program's key handler), under an
 * {@link ArActionDeceleratingLimiter} "DeceleratingLimiterForward" ({@code FORWARDS}, 40) and
 * "DeceleratingLimiterBackward" ({@code BACKWARDS}, 39). The input asks for no maximum velocity, so the
 * limiters' maximums (and decelerations), though of lower priority, go into the combined desire and
 * bound the velocity the robot is sent, as in ARIA. ARIA adds lateral limiters for robots that move sideways;
 * no simulated robot does.
 *
 * <p>ARIA's group also feeds the input from an {@code ArRatioInputJoydrive} (the computer's
 * joystick) and an {@code ArRatioInputRobotJoydrive} (the robot's): neither joystick exists in the
 * simulation, and without them those inputs set nothing, so RoboSim leaves them out. ARIA's
 * {@code addToConfig} is left out: the actions' own setters set the same values.
 */
public final class ArActionGroupRatioDrive extends ArActionGroup {
    private final ArActionRatioInput input;
    private final ArRatioInputKeydrive keydrive;
    private final ArActionDeceleratingLimiter forward;
    private final ArActionDeceleratingLimiter backward;

    /** @param robot the robot its actions are added to */
    public ArActionGroupRatioDrive(ArRobot robot) {
        super(robot);
        input = new ArActionRatioInput();
        addAction(input, 50);
        keydrive = new ArRatioInputKeydrive(robot, input);
        forward = new ArActionDeceleratingLimiter("DeceleratingLimiterForward",
                ArActionDeceleratingLimiter.LimiterType.FORWARDS);
        addAction(forward, 40);
        backward = new ArActionDeceleratingLimiter("DeceleratingLimiterBackward",
                ArActionDeceleratingLimiter.LimiterType.BACKWARDS);
        addAction(backward, 39);
    }

    /** @return its ratio input */
    public ArActionRatioInput getActionRatioInput() {
        return input;
    }

    /** @return the keydrive feeding the input (RoboSim's addition) */
    public ArRatioInputKeydrive getRatioInputKeydrive() {
        return keydrive;
    }
}
