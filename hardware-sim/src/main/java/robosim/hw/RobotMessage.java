package robosim.hw;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import robosim.protocol.Command;
import robosim.protocol.MessageDelivery;

/**
 * A message another robot sent, as this robot receives it: a string, or an object sent as JSON.
 */
public final class RobotMessage {
    /** The kind of a plain text message. */
    public static final String TEXT = "text";
    static final ObjectMapper JSON = new ObjectMapper();

    private final MessageDelivery delivery;

    RobotMessage(MessageDelivery delivery) {
        this.delivery = delivery;
    }

    /** @return the sender's name */
    public String from() {
        return delivery.from();
    }

    /** @return the robot or group it was addressed to, or {@code *} for everyone */
    public String to() {
        return delivery.to();
    }

    /** @return how it was addressed */
    public Command.Addressing mode() {
        return delivery.mode();
    }

    /** @return {@value #TEXT}, or the class name of the object sent */
    public String kind() {
        return delivery.kind();
    }

    /** @return the step in which it was sent */
    public long sentStep() {
        return delivery.sentStep();
    }

    /** @return whether it is plain text */
    public boolean isText() {
        return TEXT.equals(delivery.kind());
    }

    /** @return the text, or an object's JSON */
    public String text() {
        return delivery.body();
    }

    /**
     * Reads the payload as an object.
     *
     * @param type the class it was sent as
     * @param <T>  its type
     * @return the object
     * @throws IllegalArgumentException if the message holds something else
     */
    public <T> T as(Class<T> type) {
        if (!type.getName().equals(delivery.kind())) {
            throw new IllegalArgumentException("message from " + delivery.from() + " holds a " + delivery.kind()
                    + ", not a " + type.getName());
        }
        try {
            return JSON.readValue(delivery.body(), type);
        } catch (JsonProcessingException e) {
            throw new IllegalArgumentException("message from " + delivery.from() + " cannot be read as a "
                    + type.getName() + ": " + e.getOriginalMessage(), e);
        }
    }

    /** @return whether it holds an object of that class */
    public boolean holds(Class<?> type) {
        return type.getName().equals(delivery.kind());
    }

    @Override
    public String toString() {
        return "RobotMessage[from " + from() + " to " + to() + ", " + kind() + ": " + text() + "]";
    }
}
