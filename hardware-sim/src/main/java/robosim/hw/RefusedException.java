package robosim.hw;

import java.io.IOException;

/** The Environment answered a robot's hello with a bye: it refuses the robot, for the reason given. */
final class RefusedException extends IOException {
    private static final long serialVersionUID = 1L;
    private final String reason;
    /** The secret the refused hello presented, when it was not the robot's own (a shared link's). */
    private final String presented;

    /**
     * @param message what the robot's program is told (its connection error)
     * @param reason  the Environment's reason, without the prefix that marks a refusal
     */
    RefusedException(String message, String reason) {
        this(message, reason, null);
    }

    /**
     * @param message   what the robot's program is told
     * @param reason    the Environment's reason, without the prefix that marks a refusal
     * @param presented the secret the refused hello presented, when it was another's (a shared link's
     *                  hello, said by the robot that opened the link); null for the robot's own
     */
    RefusedException(String message, String reason, String presented) {
        super(message);
        this.reason = reason;
        this.presented = presented;
    }

    /** @return the secret the refused hello presented when it was not the robot's own, else null */
    String presented() {
        return presented;
    }

    /** @return the Environment's reason */
    String reason() {
        return reason;
    }
}
