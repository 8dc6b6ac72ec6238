package robosim.hw;

import java.io.IOException;

/** The Environment answered a robot's hello with a bye: it refuses the robot, for the reason given. */
final class RefusedException extends IOException {
    private static final long serialVersionUID = 1L;
    private final String reason;

    /**
     * @param message what the robot's program is told (its connection error)
     * @param reason  the Environment's reason, without the prefix that marks a refusal
     */
    RefusedException(String message, String reason) {
        super(message);
        this.reason = reason;
    }

    /** @return the Environment's reason */
    String reason() {
        return reason;
    }
}
