package robosim.pioneer;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;

/** Builds a packet's data field by field, little-endian as the protocol writes it. */
public final class PacketBuilder {
    private final int id;
    private final ByteArrayOutputStream out = new ByteArrayOutputStream();

    /**
     * @param id the packet's ID
     */
    public PacketBuilder(int id) {
        this.id = id;
    }

    /**
     * @param v a byte, signed or unsigned; its low 8 bits are written
     * @return this
     */
    public PacketBuilder u8(int v) {
        out.write(v);
        return this;
    }

    /**
     * @param v a 16-bit value, signed or unsigned; its low 16 bits are written
     * @return this
     */
    public PacketBuilder u16(int v) {
        out.write(v);
        out.write(v >> 8);
        return this;
    }

    /**
     * @param v a 16-bit value, clamped to −32768..32767 first
     * @return this
     */
    public PacketBuilder i16(long v) {
        return u16((int) Math.max(Short.MIN_VALUE, Math.min(Short.MAX_VALUE, v)));
    }

    /**
     * @param v a 32-bit value
     * @return this
     */
    public PacketBuilder i32(int v) {
        return u16(v).u16(v >> 16);
    }

    /**
     * @param s a string, written in Latin-1 and NUL-terminated
     * @return this
     */
    public PacketBuilder string(String s) {
        out.writeBytes(s.getBytes(StandardCharsets.ISO_8859_1));
        out.write(0);
        return this;
    }

    /**
     * A command's integer argument, as ARIA sends it: a type byte and the magnitude.
     *
     * @param v −65535 to 65535 (larger magnitudes are clamped)
     * @return this
     */
    public PacketBuilder intArgument(int v) {
        u8(v < 0 ? Commands.ARG_NEGINT : Commands.ARG_INT);
        return u16(Math.min(Math.abs(v), 0xffff));
    }

    /**
     * A command's string argument: the type byte, a length byte, the bytes (at most 199).
     *
     * @param s the string, Latin-1
     * @return this
     */
    public PacketBuilder stringArgument(String s) {
        byte[] b = s.getBytes(StandardCharsets.ISO_8859_1);
        int n = Math.min(b.length, 199);
        u8(Commands.ARG_STRING).u8(n);
        out.write(b, 0, n);
        return this;
    }

    /** @return the bytes written so far */
    public int size() {
        return out.size();
    }

    /**
     * @return the packet
     * @throws IllegalArgumentException if the data is over {@link PioneerPacket#MAX_DATA}
     */
    public PioneerPacket build() {
        return new PioneerPacket(id, out.toByteArray());
    }
}
