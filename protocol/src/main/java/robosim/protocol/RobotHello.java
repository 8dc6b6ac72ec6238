package robosim.protocol;


/**
 * The first message of a robot's connection: who it is and what body it has.
 *
 * @param name       the robot's name, as the world file declares it
 * @param robotType  the robot's type, for example {@code pioneer}
 * @param parameters the robot's own parameters, which the Environment simulates
 */
public record RobotHello(String name, String robotType, RobotParameters parameters) implements Message {
}
