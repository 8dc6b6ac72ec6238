package robosim.protocol;

import java.util.List;

/**
 * A robot's requests for one step, in the order its code made them. An empty list is a valid
 * answer: the robot has yielded and keeps its previous commands.
 *
 * @param step     the step these requests are for; must be the step the Environment has open
 * @param commands the motion commands made since the previous step
 */
public record RobotRequests(long step, List<Command> commands) implements Message {
    /** Copies the list so the record stays immutable. */
    public RobotRequests {
        commands = List.copyOf(commands);
    }
}
