package robosim.protocol;

/**
 * The Environment's answer to a {@link RobotHello}: the robot is in the world.
 *
 * @param name   the robot's name
 * @param stepMs the length of one time step in simulated milliseconds
 * @param state  the robot's state before the first step
 */
public record Welcome(String name, int stepMs, RobotState state) implements Message {
}
