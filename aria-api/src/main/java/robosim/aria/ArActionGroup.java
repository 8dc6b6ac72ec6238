package robosim.aria;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * A set of actions switched on and off together, as ARIA's {@code ArActionGroup}
 * (ArActionGroup.cpp): adding an action to the group adds it to the robot; {@link #activateExclusive()}
 * deactivates every action of the robot and then activates the group's, which is how a program
 * switches from one behaviour to another.
 */
public class ArActionGroup {
    private final ArRobot robot;
    private final List<ArAction> actions = new ArrayList<>();

    /** @param robot the robot the group's actions are added to */
    public ArActionGroup(ArRobot robot) {
        this.robot = Objects.requireNonNull(robot, "robot");
    }

    /**
     * Adds an action to the group and to the robot.
     *
     * @param action   the action
     * @param priority its priority on the robot
     */
    public synchronized void addAction(ArAction action, int priority) {
        actions.add(0, action);
        robot.addAction(action, priority);
    }

    /** @param action an action to remove from the group and from the robot */
    public synchronized void remAction(ArAction action) {
        actions.remove(action);
        robot.remAction(action);
    }

    /** Activates the group's actions; the robot's others stay as they are. */
    public synchronized void activate() {
        actions.forEach(ArAction::activate);
    }

    /** Deactivates every action of the robot, then activates the group's. */
    public synchronized void activateExclusive() {
        robot.deactivateActions();
        actions.forEach(ArAction::activate);
    }

    /** Deactivates the group's actions. */
    public synchronized void deactivate() {
        actions.forEach(ArAction::deactivate);
    }

    /** Removes the group's actions from the robot; the group still lists them. */
    public synchronized void removeActions() {
        actions.forEach(robot::remAction);
    }

    /** @return the group's actions, the last added first (ARIA's list order) */
    public synchronized List<ArAction> getActionList() {
        return List.copyOf(actions);
    }
}
