package robosim.pioneer;

import java.util.Arrays;

/**
 * One packet of the Pioneer protocol: {@code FA FB | N | ID | data | CK_hi CK_lo}, where N counts
 * the bytes after itself (the ID, the data and the two checksum bytes).
 *
 * @param id   the packet's ID: the command number of a client packet, the type of a server packet
 * @param data the bytes between the ID and the checksum
 */
public record PioneerPacket(int id, byte[] data) {
    /** The first header byte. */
    public static final int SYNC1 = 0xFA;
    /** The second header byte. */
    public static final int SYNC2 = 0xFB;
    /** The most data a packet carries: N is one byte and counts the ID and the checksum too. */
    public static final int MAX_DATA = 252;
    /** ARIA and the robot controllers keep packets under this many bytes, header included. */
    public static final int ARIA_LIMIT = 200;

    /**
     * @throws IllegalArgumentException if the ID is not a byte or the data is too long for N
     */
    public PioneerPacket {
        if (id < 0 || id > 255) {
            throw new IllegalArgumentException(id + " was supplied for a packet ID: it is 0 to 255");
        }
        if (data.length > MAX_DATA) {
            throw new IllegalArgumentException(data.length + " data bytes were supplied: a packet holds at most "
                    + MAX_DATA);
        }
        data = data.clone();
    }

    /**
     * @param id a packet ID
     * @return a packet without data
     */
    public static PioneerPacket of(int id) {
        return new PioneerPacket(id, new byte[0]);
    }

    /** @return a copy of the data */
    @Override
    public byte[] data() {
        return data.clone();
    }

    /** @return a reader over a client command's data, from its first byte, naming the command in its errors */
    public PacketData reader() {
        return new PacketData(this, "packet " + id + " (" + Commands.name(id) + ")");
    }

    /**
     * @param label what the packet is, for errors (a server packet: {@code SIP}, ...)
     * @return a reader over the data, from its first byte
     */
    public PacketData reader(String label) {
        return new PacketData(this, label);
    }

    /** @return the data's length */
    public int length() {
        return data.length;
    }

    /** @return the whole packet as sent: header, length, ID, data and checksum */
    public byte[] encode() {
        byte[] out = new byte[data.length + 6];
        out[0] = (byte) SYNC1;
        out[1] = (byte) SYNC2;
        out[2] = (byte) (data.length + 3);
        out[3] = (byte) id;
        System.arraycopy(data, 0, out, 4, data.length);
        int sum = checksum(out, 3, data.length + 1);
        out[out.length - 2] = (byte) (sum >> 8);
        out[out.length - 1] = (byte) sum;
        return out;
    }

    /**
     * The protocol's checksum: the bytes as big-endian 16-bit words summed modulo 2^16, an odd last
     * byte XOR-ed in.
     *
     * @param bytes  the buffer
     * @param offset the ID's position
     * @param length the count of bytes from the ID to the end of the data
     * @return the checksum, 0 to 65535
     */
    public static int checksum(byte[] bytes, int offset, int length) {
        int sum = 0;
        int i = offset;
        int n = length;
        while (n > 1) {
            sum = (sum + ((bytes[i] & 0xff) << 8 | bytes[i + 1] & 0xff)) & 0xffff;
            i += 2;
            n -= 2;
        }
        if (n > 0) {
            sum ^= bytes[i] & 0xff;
        }
        return sum;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof PioneerPacket p && p.id == id && Arrays.equals(p.data, data);
    }

    @Override
    public int hashCode() {
        return 31 * id + Arrays.hashCode(data);
    }

    @Override
    public String toString() {
        StringBuilder b = new StringBuilder("PioneerPacket[id=").append(id).append(", data=");
        for (int i = 0; i < Math.min(data.length, 32); i++) {
            b.append(String.format("%02x", data[i] & 0xff));
        }
        return b.append(data.length > 32 ? "..." : "").append(']').toString();
    }
}
