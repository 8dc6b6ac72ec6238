package robosim.hw;

import java.io.IOException;

/** The Environment answered a robot's hello with a bye: it refuses the robot, for the reason given. */
final class RefusedException extends IOException {
    private static final long serialVersionUID = 1L;
    private final String reason;
    /** Whether the hello refused was a shared link's (said by the robot that opened the link). */
    private final boolean byLink;
    /** The secret the link's hello presented, when {@link #byLink}. */
    private final String linkSecret;

    /**
     * @param message what the robot's program is told (its connection error)
     * @param reason  the Environment's reason, without the prefix that marks a refusal
     */
    RefusedException(String message, String reason) {
        super(message);
        this.reason = reason;
        this.byLink = false;
        this.linkSecret = null;
    }

    /**
     * A refusal of the shared link the robot joined: of the link's hello, not the robot's own.
     *
     * @param message    what the robot's program is told
     * @param reason     the Environment's reason, without the prefix that marks a refusal
     * @param linkSecret the secret the link's hello presented, or null if it presented none
     */
    static RefusedException ofLink(String message, String reason, String linkSecret) {
        return new RefusedException(message, reason, linkSecret);
    }

    private RefusedException(String message, String reason, String linkSecret) {
        super(message);
        this.reason = reason;
        this.byLink = true;
        this.linkSecret = linkSecret;
    }

    /** @return whether the hello refused was the shared link's, not the robot's own */
    boolean byLink() {
        return byLink;
    }

    /** @return the secret the link's hello presented, when {@link #byLink()}; else null */
    String linkSecret() {
        return linkSecret;
    }

    /** @return the Environment's reason */
    String reason() {
        return reason;
    }
}
