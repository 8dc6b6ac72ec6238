package robosim.hw;

import robosim.protocol.Command;

/**
 * One request of a robot's code, queued in the robot's {@code robotRequestQueue} and sent with the
 * other requests of the step once the code has yielded.
 *
 * @param command the motion command
 */
public record RobotRequest(Command command) {
}
