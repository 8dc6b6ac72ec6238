package robosim.aria;

/**
 * Driving by joystick and keyboard, guarded, as ARIA's {@code ArActionGroupTeleop}
 * (ArActionGroups.cpp): ARIA's table-sensor limiter (100), "Speed Limiter Near" (stop 300 mm, slow
 * from 600 mm, 250 mm/s; 90), "Speed Limiter Far" (300 mm, 1100 mm, 400 mm/s; 89), a backward
 * limiter (80), an {@link ArActionJoydrive} that does not stop when no button is held (70) and an
 * {@link ArActionKeydrive} (69). The limiters cap the speeds the drives ask for; the keydrive reads
 * the arrow keys of the program's key handler ({@link Aria#getKeyHandler()}). Meant to be used one
 * group at a time ({@link #activateExclusive()}).
 *
 * <p>In the simulator there is no joystick, so the joydrive wants nothing and the keydrive drives;
 * the table-sensor limiter wants nothing (no table sensors).
 */
public final class ArActionGroupTeleop extends ArActionGroup {
    private final ArActionJoydrive joydrive;
    private final ArActionKeydrive keydrive;

    /** @param robot the robot its actions are added to */
    public ArActionGroupTeleop(ArRobot robot) {
        super(robot);
        addAction(new ArActionLimiterTableSensor(), 100);
        addAction(new ArActionLimiterForwards("Speed Limiter Near", 300, 600, 250), 90);
        addAction(new ArActionLimiterForwards("Speed Limiter Far", 300, 1100, 400), 89);
        addAction(new ArActionLimiterBackwards(), 80);
        joydrive = new ArActionJoydrive();
        joydrive.setStopIfNoButtonPressed(false);
        addAction(joydrive, 70);
        keydrive = new ArActionKeydrive();
        addAction(keydrive, 69);
    }

    /**
     * The joystick's speed follows its throttle, as ARIA's.
     *
     * @param lowSpeed  the speed at the throttle's bottom, mm/s
     * @param highSpeed the speed at its top, mm/s
     */
    public void setThrottleParams(int lowSpeed, int highSpeed) {
        joydrive.setThrottleParams(lowSpeed, highSpeed);
    }

    /** @return its joydrive (RoboSim's addition: ARIA keeps it protected) */
    public ArActionJoydrive getActionJoydrive() {
        return joydrive;
    }

    /** @return its keydrive (RoboSim's addition: ARIA does not keep it) */
    public ArActionKeydrive getActionKeydrive() {
        return keydrive;
    }
}
