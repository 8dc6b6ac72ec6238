package robosim.env.net;

import java.util.Map;

/**
 * What run control may see and do of the run's sessions ({@link SessionRules}): which robots are
 * connected and when each last answered, drop one, and let a control client follow the log. Run
 * control holds this view, never the rules themselves.
 */
interface RunSessions {
    /** @return the connected robots by name, in the order they joined */
    Map<String, Connection> connectedRobots();

    /**
     * @param robot a robot's name
     * @return the last step the robot answered in time, 0 if none
     */
    long lastAnswered(String robot);

    /**
     * Takes a robot out of the run, telling it why.
     *
     * @param robot  its name
     * @param reason why
     */
    void drop(String robot, String reason);

    /** @return the Environment's log lines for the control clients that follow them */
    LogForwarding log();
}
