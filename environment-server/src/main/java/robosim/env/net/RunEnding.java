package robosim.env.net;

import java.util.Arrays;
import java.util.stream.Collectors;

/**
 * How a run ended, for machines: a results table's column, a test's check. Each has a stable
 * lower-case name for files and the wire ({@link #wireName()}); the {@link RunReport}'s
 * {@code endReason} says the same in words, with the details (which robot, which step).
 */
public enum RunEnding {
    /** The Environment's step limit ({@code env --steps}) was reached. */
    STEP_LIMIT("step-limit"),
    /** The world's own step limit ({@code <end when="steps">}) was reached. */
    WORLD_STEP_LIMIT("world-step-limit"),
    /** A robot's confirmed find of the gold had time to reach its team (the world's end rule). */
    GOLD_FOUND("gold-found"),
    /** A robot asked to end the run ({@code endRun}): it ended after the step the request came in. */
    ROBOT_ENDED("robot-ended"),
    /** Every robot had gone (the world's end rule, by default). */
    ALL_GONE("all-gone"),
    /** A robot left, was dropped or was lost, and the world ends the run when any robot goes. */
    ROBOT_LEFT("robot-left"),
    /**
     * A control client stopped it ({@code robosim control stop}, the ControlPanel), also while the
     * run a restart or load began waited for its robots.
     */
    STOPPED("stopped"),
    /**
     * It never started: the world's robots (or the awaited viewers) did not connect in time. No
     * report carries it, as {@link EnvironmentServer#run()} throws {@link IllegalStateException}
     * instead; it names such a run where every run needs a row, such as an experiment's table.
     */
    NOT_STARTED("not-started"),
    /**
     * The Environment failed under way (an exception out of its step loop, or it was interrupted).
     * No report carries it, as {@link EnvironmentServer#run()} throws instead; it names such a run
     * where every run needs a row.
     */
    FAILED("failed");

    private final String wireName;

    RunEnding(String wireName) {
        this.wireName = wireName;
    }

    /** @return its name in files and on the wire, such as {@code gold-found}; it does not change */
    public String wireName() {
        return wireName;
    }

    /**
     * @param wireName a name as {@link #wireName()} gives it
     * @return the ending of that name
     * @throws IllegalArgumentException if no ending has that name, naming the ones there are
     */
    public static RunEnding ofWireName(String wireName) {
        for (RunEnding e : values()) {
            if (e.wireName.equals(wireName)) {
                return e;
            }
        }
        throw new IllegalArgumentException("'" + wireName + "' was supplied for a run's ending: it is one of "
                + Arrays.stream(values()).map(RunEnding::wireName).collect(Collectors.joining(", ")));
    }
}
