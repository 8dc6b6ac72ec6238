package robosim.protocol.recording;

import java.io.IOException;

/**
 * A recording could not be read on: it is not a recording, is of a newer version, ends inside a
 * record, or holds a record that fails its check. The message names the file, the byte offset of
 * the record and the last step read whole; everything before that offset has been read and can be
 * replayed.
 */
public final class RecordingException extends IOException {
    private static final long serialVersionUID = 1L;

    private final long offset;
    private final long lastGoodStep;
    private final boolean truncated;

    /**
     * @param message      what went wrong, naming the file, offset and step
     * @param offset       byte offset of the record that could not be read, from the file's start
     * @param lastGoodStep the step of the last snapshot read whole, or -1 if none was
     * @param truncated    whether the file merely ends early (a run that ended abruptly), rather
     *                     than holding bad bytes
     * @param cause        the underlying failure, or {@code null}
     */
    public RecordingException(String message, long offset, long lastGoodStep, boolean truncated, Throwable cause) {
        super(message, cause);
        this.offset = offset;
        this.lastGoodStep = lastGoodStep;
        this.truncated = truncated;
    }

    /** @return the byte offset of the record that could not be read */
    public long offset() {
        return offset;
    }

    /** @return the step of the last snapshot read whole, or -1 if none was */
    public long lastGoodStep() {
        return lastGoodStep;
    }

    /** @return whether the file just ends early, as a run that ended abruptly leaves it */
    public boolean truncated() {
        return truncated;
    }
}
