package robosim.protocol;

import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;

/**
 * Reads length-prefixed frames: a 4-byte big-endian payload length, then the payload. A length of
 * zero, a negative length or one over the limit is rejected before anything is allocated.
 */
public final class FrameReader {
    /** The default largest payload accepted, 4 MiB. */
    public static final int DEFAULT_MAX_FRAME = 4 << 20;

    private final DataInputStream in;
    private final MessageCodec codec;
    private final int maxFrame;

    /**
     * @param in       the stream to read
     * @param codec    decodes payloads
     * @param maxFrame the largest payload accepted, in bytes
     */
    public FrameReader(InputStream in, MessageCodec codec, int maxFrame) {
        this.maxFrame = Frames.checkMaxFrame(maxFrame);
        this.in = new DataInputStream(new BufferedInputStream(in, 1 << 16));
        this.codec = codec;
    }

    /**
     * Reads one message.
     *
     * @return the message, or {@code null} if the stream ended cleanly between frames
     * @throws FrameException if the frame is oversized, truncated or undecodable
     * @throws IOException    if the stream fails
     */
    public Message read() throws IOException {
        int first = in.read();
        if (first < 0) {
            return null;
        }
        int length;
        try {
            length = (first << 24) | (in.readUnsignedByte() << 16) | (in.readUnsignedByte() << 8) | in.readUnsignedByte();
        } catch (EOFException e) {
            throw new FrameException("stream ended inside a frame header");
        }
        Frames.checkLength(length, maxFrame);
        byte[] payload = new byte[length];
        try {
            in.readFully(payload);
        } catch (EOFException e) {
            throw new FrameException("stream ended inside a frame of " + length + " bytes");
        }
        return codec.decode(payload);
    }
}
