package robosim.pioneer;

import java.util.Arrays;

/**
 * One part of a simulated laser scan: ID {@code 0x60} (three pose fields the client skips, then
 * the readings) or {@code 0x61} (extended: no pose fields, a reflectance byte and two spare bytes
 * after each range, then the laser's number and a flags byte). A scan of more readings than fit in
 * one packet is spread over several, each saying where its readings start.
 *
 * @param extended    whether the ID is {@code 0x61}
 * @param x           the pose field x ({@code 0x60} only; clients skip it)
 * @param y           the pose field y
 * @param th          the pose field th
 * @param total       the scan's reading count
 * @param first       the index of this packet's first reading in the scan
 * @param ranges      this packet's ranges, mm
 * @param reflectance this packet's reflectance bytes ({@code 0x61} only; zeros otherwise)
 */
public record LaserPacket(boolean extended, int x, int y, int th, int total, int first, int[] ranges,
                          int[] reflectance) {
    /** The most readings one packet carries, as MobileSim sends them. */
    public static final int MAX_READINGS = 32;

    /** Copies the arrays; a missing reflectance array is all zeros. */
    public LaserPacket {
        ranges = ranges.clone();
        reflectance = reflectance == null ? new int[ranges.length] : reflectance.clone();
    }

    @Override
    public int[] ranges() {
        return ranges.clone();
    }

    @Override
    public int[] reflectance() {
        return reflectance.clone();
    }

    /** @return the packet */
    public PioneerPacket toPacket() {
        PacketBuilder b = new PacketBuilder(extended ? Commands.LASER_EXTENDED_PACKET : Commands.LASER_PACKET);
        if (!extended) {
            b.i16(x).i16(y).i16(th);
        }
        b.u16(total).u16(first).u8(ranges.length);
        for (int i = 0; i < ranges.length; i++) {
            b.u16(Math.min(Math.max(ranges[i], 0), 0xffff));
            if (extended) {
                b.u8(reflectance[i]).u8(0).u8(0);
            }
        }
        if (extended) {
            b.u8(0).u8(0);
        }
        return b.build();
    }

    /**
     * @param p a packet with ID {@code 0x60} or {@code 0x61}
     * @return the laser packet
     * @throws PacketFormatException if it is not one, ends early, or its readings lie outside its scan
     */
    public static LaserPacket decode(PioneerPacket p) {
        boolean extended = p.id() == Commands.LASER_EXTENDED_PACKET;
        if (!extended && p.id() != Commands.LASER_PACKET) {
            throw new PacketFormatException("packet " + p.id() + " is not a laser packet (0x60 or 0x61)");
        }
        PacketData d = p.reader("laser packet");
        int x = extended ? 0 : d.i16("x");
        int y = extended ? 0 : d.i16("y");
        int th = extended ? 0 : d.i16("th");
        int total = d.u16("reading count");
        int first = d.u16("first reading");
        int n = d.u8("readings in this packet");
        if (first + n > total) {
            throw new PacketFormatException("laser packet: readings " + first + " to " + (first + n - 1)
                    + " lie outside a scan of " + total);
        }
        int[] ranges = new int[n];
        int[] refl = new int[n];
        for (int i = 0; i < n; i++) {
            ranges[i] = d.u16("range");
            if (extended) {
                refl[i] = d.u8("reflectance");
                d.u8("flags");
                d.u8("flags");
            }
        }
        return new LaserPacket(extended, x, y, th, total, first, ranges, refl);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof LaserPacket l && l.extended == extended && l.x == x && l.y == y && l.th == th
                && l.total == total && l.first == first && Arrays.equals(l.ranges, ranges)
                && Arrays.equals(l.reflectance, reflectance);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(ranges) * 31 + first;
    }

    @Override
    public String toString() {
        return "LaserPacket[extended=" + extended + ", total=" + total + ", first=" + first + ", ranges="
                + Arrays.toString(ranges) + "]";
    }
}
