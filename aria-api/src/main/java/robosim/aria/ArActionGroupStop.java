package robosim.aria;

/**
 * The robot held stopped, as ARIA's {@code ArActionGroupStop} (ArActionGroups.cpp): an
 * {@link ArActionStop} at priority 100. ARIA's predefined groups are meant to be used one at a time,
 * with {@link #activateExclusive()}.
 */
public final class ArActionGroupStop extends ArActionGroup {
    private final ArActionStop actionStop;

    /** @param robot the robot its action is added to */
    public ArActionGroupStop(ArRobot robot) {
        super(robot);
        actionStop = new ArActionStop();
        addAction(actionStop, 100);
    }

    /** @return its stop action */
    public ArActionStop getActionStop() {
        return actionStop;
    }
}
