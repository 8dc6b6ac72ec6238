package robosim.protocol;

import java.util.List;

/**
 * Requests for one step from robots of a shared link (see {@link LinkHello}): each robot's
 * {@link RobotRequests}, in one frame. Each robot's requests for a step come once, in one frame of
 * possibly several: a link sends the robots that are ready when the others are late.
 *
 * @param step   the step these requests are for; must be the step the Environment has open
 * @param robots each robot's commands, in the order its code made them
 */
public record LinkRequests(long step, List<ForRobot> robots) implements Message {
    /** Copies the list so the record stays immutable. */
    public LinkRequests {
        robots = List.copyOf(robots);
    }

    /**
     * One robot's part.
     *
     * @param robot    the robot's name
     * @param commands the commands made since the previous step
     */
    public record ForRobot(String robot, List<Command> commands) {
        /** Copies the list so the record stays immutable. */
        public ForRobot {
            commands = List.copyOf(commands);
        }
    }
}
