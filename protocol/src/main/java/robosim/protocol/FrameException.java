package robosim.protocol;

import java.io.IOException;

/** A frame broke the wire rules: oversized, truncated, undecodable or of an unknown type. */
public final class FrameException extends IOException {
    private static final long serialVersionUID = 1L;

    /** @param reason what was wrong with the frame */
    public FrameException(String reason) {
        super(reason);
    }
}
