package robosim.pioneer;

import java.nio.charset.StandardCharsets;

/**
 * Reads a packet's data field by field, little-endian as the protocol writes it. Reading past the
 * end throws a {@link PacketFormatException} naming the packet and the field, never an index error.
 */
public final class PacketData {
    private final String label;
    private final byte[] data;
    private int at;

    PacketData(PioneerPacket packet, String label) {
        this.label = label;
        this.data = packet.data();
    }

    /** @return the bytes not yet read */
    public int remaining() {
        return data.length - at;
    }

    private void need(int n, String field) {
        if (remaining() < n) {
            throw new PacketFormatException(label + " of " + data.length + " data bytes ends before its " + field + " (byte " + at + ", " + n + " bytes)");
        }
    }

    /**
     * @param field the field's name, for the error
     * @return an unsigned byte
     */
    public int u8(String field) {
        need(1, field);
        return data[at++] & 0xff;
    }

    /**
     * @param field the field's name, for the error
     * @return a signed byte
     */
    public int i8(String field) {
        need(1, field);
        return data[at++];
    }

    /**
     * @param field the field's name, for the error
     * @return an unsigned 16-bit value
     */
    public int u16(String field) {
        need(2, field);
        int v = data[at] & 0xff | (data[at + 1] & 0xff) << 8;
        at += 2;
        return v;
    }

    /**
     * @param field the field's name, for the error
     * @return a signed 16-bit value
     */
    public int i16(String field) {
        return (short) u16(field);
    }

    /**
     * @param field the field's name, for the error
     * @return a signed 32-bit value
     */
    public int i32(String field) {
        need(4, field);
        int v = data[at] & 0xff | (data[at + 1] & 0xff) << 8 | (data[at + 2] & 0xff) << 16 | (data[at + 3] & 0xff) << 24;
        at += 4;
        return v;
    }

    /**
     * @param field the field's name, for the error
     * @return a NUL-terminated string (Latin-1); a string that runs to the end without its NUL ends there
     */
    public String string(String field) {
        need(1, field);
        int start = at;
        while (at < data.length && data[at] != 0) {
            at++;
        }
        String s = new String(data, start, at - start, StandardCharsets.ISO_8859_1);
        if (at < data.length) {
            at++;
        }
        return s;
    }

    /**
     * A command's integer argument: a type byte ({@link Commands#ARG_INT} or {@link Commands#ARG_NEGINT})
     * and an unsigned 16-bit magnitude.
     *
     * @param field the field's name, for the error
     * @return the argument, −65535 to 65535
     */
    public int intArgument(String field) {
        int type = u8(field + "'s type");
        int magnitude = u16(field);
        if (type == Commands.ARG_NEGINT) {
            return -magnitude;
        }
        if (type != Commands.ARG_INT) {
            throw new PacketFormatException(String.format("%s: %s's type byte is 0x%02x: it is 0x3b (positive)"
                    + " or 0x1b (negative)", label, field, type));
        }
        return magnitude;
    }

    /**
     * A command's string argument: the type byte {@link Commands#ARG_STRING}, a length byte, the bytes.
     *
     * @param field the field's name, for the error
     * @return the string (Latin-1)
     */
    public String stringArgument(String field) {
        int type = u8(field + "'s type");
        if (type != Commands.ARG_STRING) {
            throw new PacketFormatException(String.format("%s: %s's type byte is 0x%02x: a string is 0x2b",
                    label, field, type));
        }
        int n = u8(field + "'s length");
        need(n, field);
        String s = new String(data, at, n, StandardCharsets.ISO_8859_1);
        at += n;
        int nul = s.indexOf('\0');
        return nul >= 0 ? s.substring(0, nul) : s;
    }
}
