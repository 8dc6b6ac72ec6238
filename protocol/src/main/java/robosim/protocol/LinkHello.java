package robosim.protocol;

/**
 * The first message of a connection that carries many robots of one client JVM (a shared link).
 * After it the client sends a {@link RobotHello} for each robot, answered one by one with a
 * {@link Welcome} or a {@link Bye} naming the robot; each step the Environment sends one
 * {@link TimeSteps} for all the link's robots and the client answers with {@link LinkRequests},
 * once all its robots have yielded or in parts when some are slow. A connection whose first message
 * is a {@link RobotHello} carries that robot alone, with {@link TimeStep} and {@link RobotRequests}.
 *
 * @param client who opens the link, for the Environment's log
 */
public record LinkHello(String client) implements Message {
}
