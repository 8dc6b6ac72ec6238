package robosim.aria;

import java.util.List;

/**
 * Combines what the robot's actions want into one desire each cycle, as ARIA's {@code ArResolver}.
 * The robot's default is {@link ArPriorityResolver}; another can be set with
 * {@link ArRobot#setResolver}.
 */
public abstract class ArResolver {
    /**
     * An action as the robot holds it, with its priority.
     *
     * @param priority higher fires first
     * @param action   the action
     */
    public record Entry(int priority, ArAction action) {
    }

    private final String name;
    private final String description;

    /**
     * @param name        the resolver's name
     * @param description what it does
     */
    protected ArResolver(String name, String description) {
        this.name = name;
        this.description = description;
    }

    /**
     * @param actions    the robot's actions in firing order: highest priority first, and among equal
     *                   priorities the one added last first (ARIA's order)
     * @param robot      the robot, for its heading
     * @param logActions whether to log each action's desire
     * @return the combined desire, or null for none
     */
    public abstract ArActionDesired resolve(List<Entry> actions, ArRobot robot, boolean logActions);

    /** @return the resolver's name */
    public String getName() {
        return name;
    }

    /** @return what the resolver does */
    public String getDescription() {
        return description;
    }
}
