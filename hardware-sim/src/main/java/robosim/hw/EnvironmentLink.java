package robosim.hw;

import java.io.IOException;
import java.util.List;
import java.util.function.Supplier;
import robosim.protocol.RobotHello;
import robosim.protocol.Welcome;

/**
 * How one robot's {@link HardwareSimulator} reaches the Environment: a connection of its own, or
 * its part of a connection that the robots of one JVM share (see {@link EnvironmentLinks}). The
 * simulator opens it once, then sends one set of requests per step until it says bye or the link
 * ends.
 */
public interface EnvironmentLink {
    /**
     * Connects, says hello and waits (bounded) for the Environment's welcome. From then on each
     * step goes to {@code receiver}, on a thread of the link; the first may come before this
     * returns. The link tells the receiver how it ended ({@link StepReceiver#ended}): the
     * Environment's bye, or the Environment lost (the connection closed or broke, or nothing came,
     * neither a step nor a keep-alive, for {@link HardwareOptions#lostAfterMs()}).
     *
     * @param hello    the robot's name, type and parameters
     * @param receiver where the steps go
     * @return the welcome, with the robot's state before the first step
     * @throws IOException if the connection fails or the Environment refuses the robot
     */
    Welcome open(RobotHello hello, StepReceiver receiver) throws IOException;

    /**
     * Opens as {@link #open(RobotHello, StepReceiver)} does, presenting the secret {@code secret}
     * gives once the connection is open (looked up then, not before).
     *
     * @param hello    the robot's name, type and parameters
     * @param secret   gives the run secret to present; null to present the hello's own
     * @param receiver where the steps go
     * @return the welcome
     * @throws IOException if the connection fails or the Environment refuses the robot
     */
    default Welcome open(RobotHello hello, Supplier<String> secret, StepReceiver receiver) throws IOException {
        return open(secret == null ? hello : hello.withToken(secret.get()), receiver);
    }

    /**
     * @return the name the robot's own server gives it, once open (a Pioneer robot server's, from its
     *     handshake), or null when the robot is the Environment's and its name is the program's
     */
    default String serverRobotName() {
        return null;
    }

    /**
     * Sends the robot's requests for a step.
     *
     * @param step     the step open
     * @param requests what the robot's code requested since its previous yield, in order
     * @throws IOException if the link cannot send
     */
    void send(long step, List<RobotRequest> requests) throws IOException;

    /**
     * Says bye, then closes: the robot leaves the run.
     *
     * @param reason for the Environment's log
     */
    void bye(String reason);

    /** Closes without a word; no step is delivered after it returns. Closing twice does nothing. */
    void close();

    /** @return the Environment's host and port, {@code host:port}, for messages */
    String environment();
}
