package robosim.protocol;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;

/** Writes length-prefixed frames (see {@link FrameReader}); one flush per message. */
public final class FrameWriter {
    private final OutputStream out;
    private final MessageCodec codec;

    /**
     * @param out   the stream to write
     * @param codec encodes payloads
     */
    public FrameWriter(OutputStream out, MessageCodec codec) {
        this.out = new BufferedOutputStream(out, 1 << 16);
        this.codec = codec;
    }

    /**
     * Writes and flushes one message.
     *
     * @param message the message
     * @throws IOException if the stream fails
     */
    public synchronized void write(Message message) throws IOException {
        ByteBuffer frame = frame(codec, message);
        out.write(frame.array(), 0, frame.limit());
        out.flush();
    }

    /**
     * Encodes one message as a whole frame, for non-blocking writers (the same frame can go to
     * many peers: give each a duplicate).
     *
     * @param codec   encodes the payload
     * @param message the message
     * @return the frame, ready to write
     */
    public static ByteBuffer frame(MessageCodec codec, Message message) {
        return Frames.frame(codec.encode(message));
    }
}
