package robosim.protocol;

import java.io.IOException;

/**
 * A frame broke the wire rules: oversized, truncated, undecodable or of an unknown type; or, as an
 * {@link InvalidValueException}, it held a value that breaks a rule of its message.
 */
public class FrameException extends IOException {
    private static final long serialVersionUID = 1L;

    /** @param reason what was wrong with the frame */
    public FrameException(String reason) {
        super(reason);
    }
}
