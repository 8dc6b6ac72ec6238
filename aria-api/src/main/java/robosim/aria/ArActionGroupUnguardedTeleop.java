package robosim.aria;

/**
 * Driving by joystick and keyboard with no limiters, as ARIA's
 * {@code ArActionGroupUnguardedTeleop} (ArActionGroups.cpp): an {@link ArActionJoydrive} that does
 * not stop when no button is held (70) and an {@link ArActionKeydrive} (69), nothing else: the robot
 * drives into what is in front of it. Meant to be used one group at a time
 * ({@link #activateExclusive()}). In the simulator there is no joystick: the keydrive drives.
 */
public final class ArActionGroupUnguardedTeleop extends ArActionGroup {
    private final ArActionJoydrive joydrive;
    private final ArActionKeydrive keydrive;

    /** @param robot the robot its actions are added to */
    public ArActionGroupUnguardedTeleop(ArRobot robot) {
        super(robot);
        joydrive = new ArActionJoydrive();
        joydrive.setStopIfNoButtonPressed(false);
        addAction(joydrive, 70);
        keydrive = new ArActionKeydrive();
        addAction(keydrive, 69);
    }

    /**
     * @param lowSpeed  the joystick's speed at the throttle's bottom, mm/s
     * @param highSpeed at its top, mm/s
     */
    public void setThrottleParams(int lowSpeed, int highSpeed) {
        joydrive.setThrottleParams(lowSpeed, highSpeed);
    }

    /** @return its joydrive (RoboSim's addition) */
    public ArActionJoydrive getActionJoydrive() {
        return joydrive;
    }

    /** @return its keydrive (RoboSim's addition) */
    public ArActionKeydrive getActionKeydrive() {
        return keydrive;
    }
}
