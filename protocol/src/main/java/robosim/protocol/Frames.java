package robosim.protocol;

import java.nio.ByteBuffer;

/** The frame format's rules, in one place for the stream and the buffer codecs. */
final class Frames {
    private Frames() {
    }

    static int checkMaxFrame(int maxFrame) {
        if (maxFrame <= 0) {
            throw new IllegalArgumentException(maxFrame + " was supplied for maxFrame: it must be greater than 0");
        }
        return maxFrame;
    }

    /** Refuses a payload length of 0, a negative one, or one over the limit, before anything is allocated. */
    static void checkLength(int length, int maxFrame) throws FrameException {
        if (length == 0) {
            throw new FrameException("frame of 0 bytes: a frame holds at least 1 byte");
        }
        if (length < 0 || length > maxFrame) {
            throw new FrameException("frame of " + Integer.toUnsignedString(length)
                    + " bytes exceeds the limit of " + maxFrame + " bytes");
        }
    }

    /** A whole frame: the 4-byte big-endian length, then the payload. */
    static ByteBuffer frame(byte[] payload) {
        ByteBuffer b = ByteBuffer.allocate(4 + payload.length);
        b.putInt(payload.length).put(payload).flip();
        return b;
    }
}
