package robosim.protocol;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;

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
        byte[] payload = codec.encode(message);
        int n = payload.length;
        out.write(n >>> 24);
        out.write(n >>> 16);
        out.write(n >>> 8);
        out.write(n);
        out.write(payload);
        out.flush();
    }
}
