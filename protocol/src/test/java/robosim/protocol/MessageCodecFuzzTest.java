package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static robosim.protocol.RecordAssert.assertDeepEquals;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import robosim.protocol.MessageCodec.Format;

/**
 * Seeded-random properties of the codec (see {@link Fuzz} to replay a case or run more): every
 * valid message comes back equal; a damaged or hostile payload decodes to a message or fails with
 * a {@link FrameException} that says why, never with another exception; and whatever it decodes
 * to can be encoded again, as the Environment does when it passes a robot's words on.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class MessageCodecFuzzTest {

    @ParameterizedTest
    @EnumSource(Format.class)
    void everyRandomValidMessageDecodesToAnEqualMessage(Format format) {
        MessageCodec codec = new MessageCodec(format);
        Fuzz.cases(0x5EED_0001L, 2000, fuzz -> {
            Message m = new RandomMessages(fuzz.random()).any();
            fuzz.input(String.valueOf(m));

            assertDeepEquals(m, codec.decode(codec.encode(m)));
        });
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void aDamagedPayloadDecodesOrFailsWithAFrameException(Format format) {
        MessageCodec codec = new MessageCodec(format);
        Fuzz.cases(0x5EED_0002L, 2500, fuzz -> {
            byte[] payload = fuzz.mutate(codec.encode(new RandomMessages(fuzz.random()).any()));
            fuzz.input(payload);

            decodesOrFailsClearly(codec, payload);
        });
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void aHostileMessageDecodesOrFailsWithAFrameException(Format format) {
        MessageCodec codec = new MessageCodec(format);
        Fuzz.cases(0x5EED_0003L, 2000, fuzz -> {
            Message valid = new RandomMessages(fuzz.random()).any();
            byte[] payload = new PayloadMutator(fuzz.random()).mutate(valid, format == Format.SMILE);
            fuzz.input(payload);

            decodesOrFailsClearly(codec, payload);
        });
    }

    /**
     * The codec's contract for any bytes: a message that can be encoded again to an equal message,
     * or a {@link FrameException} with a reason. Anything else escapes and fails the case.
     */
    static void decodesOrFailsClearly(MessageCodec codec, byte[] payload) {
        Message m;
        try {
            m = codec.decode(payload);
        } catch (FrameException e) {
            assertNotNull(e.getMessage(), "a frame error says why");
            assertFalse(e.getMessage().isBlank(), "a frame error says why");
            return;
        }
        assertNotNull(m, "a decoded payload is a message");
        try {
            assertDeepEquals(m, codec.decode(codec.encode(m)));
        } catch (FrameException e) {
            throw new AssertionError("a decoded " + m.getClass().getSimpleName() + " does not decode again: " + e, e);
        }
    }
}
