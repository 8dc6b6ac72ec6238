package robosim.protocol;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Decodes length-prefixed frames (see {@link FrameReader}) from buffers that arrive in pieces, for
 * non-blocking I/O. Frames may be split anywhere; a length over the limit is rejected as soon as
 * its header is complete, before anything is allocated. The space for a payload grows with the
 * bytes that arrive (from {@value #FIRST_ALLOCATION} bytes, doubling), so a peer that announces a
 * large frame and sends nothing more holds little memory.
 */
public final class FrameDecoder {
    private final MessageCodec codec;
    private final int maxFrame;
    /** The most a payload is given before its bytes arrive. */
    static final int FIRST_ALLOCATION = 64 << 10;

    private final ByteBuffer header = ByteBuffer.allocate(4);
    private byte[] payload;
    private int expected;
    private int filled;

    /**
     * @param codec    decodes payloads
     * @param maxFrame the largest payload accepted, in bytes
     */
    public FrameDecoder(MessageCodec codec, int maxFrame) {
        this.codec = codec;
        this.maxFrame = Frames.checkMaxFrame(maxFrame);
    }

    /**
     * Consumes every byte of {@code in} and returns the messages completed by them.
     *
     * @param in bytes just received, ready to read
     * @return the complete messages, in order; empty if none completed
     * @throws FrameException if a frame is oversized, empty or undecodable
     */
    public List<Message> decode(ByteBuffer in) throws FrameException {
        List<Message> out = new ArrayList<>(1);
        while (in.hasRemaining()) {
            if (payload == null) {
                while (header.hasRemaining() && in.hasRemaining()) {
                    header.put(in.get());
                }
                if (header.hasRemaining()) {
                    break;
                }
                int length = header.getInt(0);
                header.clear();
                Frames.checkLength(length, maxFrame);
                expected = length;
                payload = new byte[Math.min(length, FIRST_ALLOCATION)];
                filled = 0;
            }
            if (filled == payload.length) {
                payload = Arrays.copyOf(payload, (int) Math.min(expected, 2L * payload.length));
            }
            int n = Math.min(in.remaining(), payload.length - filled);
            in.get(payload, filled, n);
            filled += n;
            if (filled == expected) {
                byte[] done = payload;
                payload = null;
                out.add(codec.decode(done));
            }
        }
        return out;
    }

    /** @return whether a frame has been started and not finished */
    public boolean midFrame() {
        return payload != null || header.position() > 0;
    }
}
