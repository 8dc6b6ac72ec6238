package robosim.aria;

/**
 * Teleoperation through ratios with no limiters, as ARIA's {@code ArActionGroupRatioDriveUnsafe}
 * (ArActionGroups.cpp): an {@link ArActionRatioInput} (50) fed by an {@link ArRatioInputKeydrive},
 * nothing else. As in {@link ArActionGroupRatioDrive}, ARIA's joystick inputs are left out: the
 * simulation has no joystick on the computer or the robot.
 */
public final class ArActionGroupRatioDriveUnsafe extends ArActionGroup {
    private final ArActionRatioInput input;
    private final ArRatioInputKeydrive keydrive;

    /** @param robot the robot its actions are added to */
    public ArActionGroupRatioDriveUnsafe(ArRobot robot) {
        super(robot);
        input = new ArActionRatioInput();
        addAction(input, 50);
        keydrive = new ArRatioInputKeydrive(robot, input);
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
