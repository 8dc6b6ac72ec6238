package robosim.pioneer;

import java.util.Arrays;

/**
 * Cuts a byte stream into packets. Bytes before a packet's {@code FA FB} header are skipped; a
 * length below 3, or a checksum that does not match, drops the packet. After a bad packet the
 * decoder looks for the next header from the byte after the bad one's header, not after its
 * claimed length, so that a corrupt length byte cannot swallow the good packets that follow. Every
 * drop is reported to the {@link Listener} with the reason; nothing is thrown. Memory is bounded:
 * at most one packet's worth of bytes is kept between calls.
 */
public final class PacketDecoder {
    /** Where the decoder's output goes. */
    public interface Listener {
        /**
         * A whole packet with a good checksum.
         *
         * @param packet the packet
         */
        void packet(PioneerPacket packet);

        /**
         * Bytes were dropped.
         *
         * @param reason what was wrong: skipped bytes, a bad length or a bad checksum
         */
        void dropped(String reason);
    }

    private final Listener listener;
    private byte[] buffer = new byte[512];
    private int length;
    private long skipped;

    /**
     * @param listener receives the packets and the reasons for drops, on the thread that feeds
     */
    public PacketDecoder(Listener listener) {
        this.listener = listener;
    }

    /**
     * Feeds bytes as they arrive; whole packets go to the listener before this returns.
     *
     * @param bytes  the buffer
     * @param offset the first byte
     * @param count  how many
     */
    public void feed(byte[] bytes, int offset, int count) {
        if (length + count > buffer.length) {
            buffer = Arrays.copyOf(buffer, Math.max(buffer.length * 2, length + count));
        }
        System.arraycopy(bytes, offset, buffer, length, count);
        length += count;
        int at = decode();
        System.arraycopy(buffer, at, buffer, 0, length - at);
        length -= at;
        if (buffer.length > 4096 && length < 512) {
            buffer = Arrays.copyOf(buffer, 512);
        }
    }

    /** @return the bytes held for a packet not yet complete */
    public int pending() {
        return length;
    }

    /** @return the position of the first byte not consumed */
    private int decode() {
        int at = 0;
        while (true) {
            int header = findHeader(at);
            if (header < 0) {
                // keep a trailing FA: it may be the start of a header
                int keep = length > at && (buffer[length - 1] & 0xff) == PioneerPacket.SYNC1 ? 1 : 0;
                skip(length - keep - at);
                return length - keep;
            }
            skip(header - at);
            at = header;
            if (length - at < 3) {
                return at;
            }
            int n = buffer[at + 2] & 0xff;
            if (n < 3) {
                flushSkipped();
                listener.dropped("a packet's length byte is " + n + ": it counts the ID and the two checksum bytes,"
                        + " so it is at least 3");
                at += 2;
                continue;
            }
            if (length - at < 3 + n) {
                return at;
            }
            int expected = (buffer[at + 1 + n] & 0xff) << 8 | buffer[at + 2 + n] & 0xff;
            int actual = PioneerPacket.checksum(buffer, at + 3, n - 2);
            if (expected != actual) {
                flushSkipped();
                listener.dropped(String.format("a packet with ID %d and length byte %d has checksum 0x%04x but its bytes"
                        + " sum to 0x%04x", buffer[at + 3] & 0xff, n, expected, actual));
                at += 2;
                continue;
            }
            flushSkipped();
            listener.packet(new PioneerPacket(buffer[at + 3] & 0xff, Arrays.copyOfRange(buffer, at + 4, at + 1 + n)));
            at += 3 + n;
        }
    }

    private int findHeader(int from) {
        for (int i = from; i + 1 < length; i++) {
            if ((buffer[i] & 0xff) == PioneerPacket.SYNC1 && (buffer[i + 1] & 0xff) == PioneerPacket.SYNC2) {
                return i;
            }
        }
        return -1;
    }

    private void skip(int n) {
        skipped += n;
        if (skipped >= 4096) {
            flushSkipped();
        }
    }

    private void flushSkipped() {
        if (skipped > 0) {
            long n = skipped;
            skipped = 0;
            listener.dropped(n + " byte" + (n == 1 ? "" : "s") + " outside any packet (no FA FB header) skipped");
        }
    }
}
