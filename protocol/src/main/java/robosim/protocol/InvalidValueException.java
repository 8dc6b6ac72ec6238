package robosim.protocol;

/**
 * A frame was well formed, but a value in it breaks a rule of the record it encodes, such as a
 * command's non-finite velocity: the message cannot exist. The message of the exception is the
 * rule's own text, for the receiver to put in its own words (which robot, which step).
 */
public final class InvalidValueException extends FrameException {
    private static final long serialVersionUID = 1L;

    /** @param rule the broken rule, as the record states it */
    public InvalidValueException(String rule) {
        super(rule);
    }
}
