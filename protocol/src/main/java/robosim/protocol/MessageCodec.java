package robosim.protocol;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.util.JsonRecyclerPools;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.exc.InvalidTypeIdException;
import com.fasterxml.jackson.databind.exc.ValueInstantiationException;
import com.fasterxml.jackson.databind.module.SimpleModule;
import com.fasterxml.jackson.dataformat.smile.SmileFactory;
import com.fasterxml.jackson.dataformat.smile.databind.SmileMapper;
import java.io.IOException;
import java.io.UncheckedIOException;

/**
 * Turns messages into frame payloads and back, with Jackson. Smile (Jackson's binary JSON) is the
 * wire format, chosen by measurement (see docs/BENCHMARKS.md); JSON is kept for debugging and for
 * the comparison.
 */
public final class MessageCodec {
    /** The payload encodings the codec speaks. */
    public enum Format { SMILE, JSON }

    private final ObjectMapper mapper;

    /** A codec for the wire format, Smile. */
    public MessageCodec() {
        this(Format.SMILE);
    }

    /**
     * The codec's buffers are recycled through one pool for all the threads that use it (Jackson's
     * default keeps one set per thread: with a thousand robot threads each encoding, now and then,
     * a shared link's frame, a thousand buffers of that frame's size stayed alive).
     *
     * @param format the payload encoding
     */
    public MessageCodec(Format format) {
        ObjectMapper m = format == Format.SMILE
                ? new SmileMapper(SmileFactory.builder().recyclerPool(JsonRecyclerPools.newConcurrentDequePool()).build())
                : new ObjectMapper(JsonFactory.builder().recyclerPool(JsonRecyclerPools.newConcurrentDequePool()).build());
        m.enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES);
        m.enable(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES);
        m.registerModule(new SimpleModule("robosim-text").addDeserializer(String.class, new UnicodeTextDeserializer()));
        this.mapper = m;
    }

    /**
     * @param message the message
     * @return its payload bytes
     */
    public byte[] encode(Message message) {
        try {
            return mapper.writeValueAsBytes(message);
        } catch (JsonProcessingException e) {
            throw new UncheckedIOException("cannot encode " + message.getClass().getSimpleName(), e);
        }
    }

    /**
     * Decodes a payload from a peer. The reason of every exception is safe to log in one line: what
     * the peer wrote is quoted with characters outside printable ASCII escaped, and cut short.
     *
     * @param payload a frame's payload
     * @return the message it holds
     * @throws InvalidValueException if the payload is a message whose values break a rule of their
     *                               record, such as a non-finite velocity
     * @throws FrameException        if the payload is not a message of a known type, or holds text
     *                               that is not valid UTF-8
     */
    public Message decode(byte[] payload) throws FrameException {
        Message m;
        try {
            m = mapper.readValue(payload, Message.class);
        } catch (InvalidTypeIdException e) {
            if (e.getTypeId() == null) {
                throw undecodable("no message type in frame of " + payload.length + " bytes: ", e.getOriginalMessage());
            }
            throw undecodable("unknown message type ", "'" + e.getTypeId() + "'");
        } catch (JsonProcessingException e) {
            // a record's constructor refused a value: the frame was sound, the message breaks a rule
            if (e instanceof ValueInstantiationException && e.getCause() instanceof IllegalArgumentException rule) {
                throw new InvalidValueException(printable(rule.getMessage()));
            }
            throw undecodable("undecodable frame of " + payload.length + " bytes: ", e.getOriginalMessage());
        } catch (IOException e) {
            throw undecodable("undecodable frame of " + payload.length + " bytes: ", e.getMessage());
        } catch (RuntimeException e) {
            // Jackson's own slip on hostile bytes (a type name that is binary data met a null check)
            throw undecodable("undecodable frame of " + payload.length + " bytes: ", "the decoder failed with " + e);
        }
        if (m == null) {
            throw new FrameException("empty message: a frame of " + payload.length + " bytes holds null");
        }
        return m;
    }

    private static FrameException undecodable(String what, String quoted) {
        return new FrameException(what + printable(quoted));
    }

    /** The peer's words, escaped (see {@link RobotHello#printable(String, int)}) and cut after 300 characters. */
    private static String printable(String text) {
        return RobotHello.printable(text, 300);
    }
}
