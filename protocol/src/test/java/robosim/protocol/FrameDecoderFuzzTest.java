package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.protocol.RecordAssert.assertDeepEquals;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Seeded-random streams of frames, valid, damaged and with hostile length headers, through the
 * {@link FrameDecoder} and the {@link FrameReader} (see {@link Fuzz} to replay a case or run more).
 * However the bytes arrive, the decoder fails at the same frame with the same error as the reader,
 * and the messages it gives are the reader's; neither throws anything but a
 * {@link FrameException}, and neither allocates more than its frame limit for a frame, whatever
 * length a header claims.
 *
 * <p>One difference is allowed: the decoder throws for a bad frame without returning the messages
 * completed earlier in the same buffer, so it may give fewer of the reader's messages before the
 * error, depending on how the bytes were split.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class FrameDecoderFuzzTest {
    private static final int MAX_FRAME = FrameReader.DEFAULT_MAX_FRAME;
    /** What decoding may allocate besides the frame itself: the codec's work, per byte and in all. */
    private static final long PER_BYTE = 64;
    private static final long SLACK = 512 << 10;
    private static final MessageCodec CODEC = new MessageCodec();
    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();

    /** What a decoder made of a stream: the messages, then the error that stopped it (or null). */
    private record Outcome(List<Message> messages, String error, boolean midFrame) { }

    @Test
    void theDecoderAgreesWithTheReaderWhereverTheStreamIsSplit() {
        Fuzz.cases(0x5EED_0101L, 2000, fuzz -> {
            byte[] stream = stream(fuzz);
            fuzz.input(stream);

            Outcome read = read(stream);
            Outcome whole = decode(stream, new int[] {stream.length});
            Outcome pieces = decode(stream, pieces(fuzz, stream.length));

            assertEquals(whole.error(), pieces.error());
            assertEquals(whole.midFrame(), pieces.midFrame());
            agree(read, whole);
            agree(read, pieces);
        });
    }

    private static void agree(Outcome read, Outcome decoded) {
        if (decoded.error() == null) {
            assertDeepEquals(read.messages(), decoded.messages());
        } else {
            assertTrue(decoded.messages().size() <= read.messages().size(), "more messages than the reader's");
            assertDeepEquals(read.messages().subList(0, decoded.messages().size()), decoded.messages());
        }
        if (decoded.error() != null) {
            assertEquals(decoded.error(), read.error());
        } else if (decoded.midFrame()) {
            assertTrue(read.error() != null && read.error().startsWith("stream ended inside a frame"), read.error());
        } else {
            assertEquals(null, read.error());
        }
    }

    /** One to four frames: most valid, some with a damaged payload or a length no writer would put. */
    private static byte[] stream(Fuzz fuzz) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        RandomMessages messages = new RandomMessages(fuzz.random());
        for (int n = 1 + fuzz.random().nextInt(4); n > 0; n--) {
            byte[] payload = CODEC.encode(messages.any());
            if (fuzz.random().nextInt(4) == 0) {
                payload = fuzz.mutate(payload);
            }
            int length = switch (fuzz.random().nextInt(8)) {
                case 0 -> Fuzz.EDGE_INTS[fuzz.random().nextInt(Fuzz.EDGE_INTS.length)];
                case 1 -> payload.length + fuzz.random().nextInt(3) - 1;
                default -> payload.length;
            };
            out.write(ByteBuffer.allocate(4).putInt(length).array());
            out.write(payload);
        }
        byte[] bytes = out.toByteArray();
        return fuzz.random().nextInt(4) == 0 ? fuzz.mutate(bytes) : bytes;
    }

    /** @return the sizes of random pieces that add up to {@code length} */
    private static int[] pieces(Fuzz fuzz, int length) {
        List<Integer> sizes = new ArrayList<>();
        for (int left = length; left > 0; ) {
            int n = Math.min(left, 1 + fuzz.random().nextInt(fuzz.random().nextBoolean() ? 8 : 256));
            sizes.add(n);
            left -= n;
        }
        return sizes.stream().mapToInt(Integer::intValue).toArray();
    }

    private static Outcome decode(byte[] stream, int[] pieces) {
        FrameDecoder decoder = new FrameDecoder(CODEC, MAX_FRAME);
        List<Message> messages = new ArrayList<>();
        int at = 0;
        for (int size : pieces) {
            ByteBuffer piece = ByteBuffer.wrap(stream, at, size);
            at += size;
            long before = THREADS.getCurrentThreadAllocatedBytes();
            try {
                messages.addAll(decoder.decode(piece));
            } catch (FrameException e) {
                return new Outcome(messages, e.getMessage(), decoder.midFrame());
            } finally {
                allocatedAtMost(THREADS.getCurrentThreadAllocatedBytes() - before, size);
            }
        }
        return new Outcome(messages, null, decoder.midFrame());
    }

    private static Outcome read(byte[] stream) throws IOException {
        FrameReader reader = new FrameReader(new ByteArrayInputStream(stream), CODEC, MAX_FRAME);
        List<Message> messages = new ArrayList<>();
        while (true) {
            long before = THREADS.getCurrentThreadAllocatedBytes();
            try {
                Message m = reader.read();
                if (m == null) {
                    return new Outcome(messages, null, false);
                }
                messages.add(m);
            } catch (FrameException e) {
                return new Outcome(messages, e.getMessage(), false);
            } finally {
                allocatedAtMost(THREADS.getCurrentThreadAllocatedBytes() - before, stream.length);
            }
        }
    }

    private static void allocatedAtMost(long allocated, int bytesIn) {
        long limit = MAX_FRAME + PER_BYTE * bytesIn + SLACK;
        assertTrue(allocated <= limit, "decoding " + bytesIn + " bytes allocated " + allocated
                + " bytes, over the frame limit of " + MAX_FRAME + " and the codec's share");
    }
}
