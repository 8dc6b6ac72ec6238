package robosim.viewer.net;

import java.io.IOException;

/**
 * A {@link ViewerClient} could not go on: the Environment could not be reached, went silent past
 * the read timeout, or broke the protocol. The message names the peer and the reason.
 */
public final class ViewerException extends IOException {
    private static final long serialVersionUID = 1L;
    /** The Environment's reason when it refused the viewer's hello, else null. */
    private final String refusal;

    /**
     * @param message what went wrong, naming the peer
     * @param cause   the underlying failure, or {@code null}
     */
    public ViewerException(String message, Throwable cause) {
        this(message, cause, null);
    }

    ViewerException(String message, Throwable cause, String refusal) {
        super(message, cause);
        this.refusal = refusal;
    }

    /** @return the Environment's reason when it refused the viewer's hello, else null */
    String refusal() {
        return refusal;
    }
}
