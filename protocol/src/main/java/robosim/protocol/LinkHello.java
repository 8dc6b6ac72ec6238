package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;

/**
 * The first message of a connection that carries many robots of one client JVM (a shared link).
 * After it the client sends a {@link RobotHello} for each robot, answered one by one with a
 * {@link Welcome} or a {@link Bye} naming the robot; each step the Environment sends one
 * {@link TimeSteps} for all the link's robots and the client answers with {@link LinkRequests},
 * once all its robots have yielded or in parts when some are slow. A connection whose first message
 * is a {@link RobotHello} carries that robot alone, with {@link TimeStep} and {@link RobotRequests}.
 *
 * @param client who opens the link, for the Environment's log
 * @param token  the run secret (see {@link RunSecret}), or null when the run has none; the link's
 *               robots are admitted on it without presenting it again
 */
public record LinkHello(String client, @JsonInclude(JsonInclude.Include.NON_NULL) String token) implements Message {
    /** @param client who opens the link; no secret is presented */
    public LinkHello(String client) {
        this(client, null);
    }

    /** @return the hello with the secret masked */
    @Override
    public String toString() {
        return "LinkHello[client=" + client + ", token=" + RunSecret.masked(token) + "]";
    }
}
