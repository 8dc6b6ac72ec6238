package robosim.env.net;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The robots that went before the end of the run, as the session rules see them go. Only the first
 * way a robot goes counts (a robot lost is then dropped from the run too), and only once the run has
 * started: a robot may leave and come back before the first step.
 */
final class Departures {
    private final Map<String, Departure> byRobot = new LinkedHashMap<>();

    /**
     * Marks a robot gone, unless it already is or the run has not started.
     *
     * @param robot  the robot
     * @param kind   how it went
     * @param step   the step open, or the last step run; 0 before the run
     * @param reason why
     */
    void mark(String robot, Departure.Kind kind, long step, String reason) {
        if (step > 0) {
            byRobot.putIfAbsent(robot, new Departure(robot, kind, step, reason));
        }
    }

    /** @return the robots gone, in the order they went */
    List<Departure> list() {
        return new ArrayList<>(byRobot.values());
    }
}
