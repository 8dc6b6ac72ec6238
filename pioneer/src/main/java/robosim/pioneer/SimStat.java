package robosim.pioneer;

/**
 * The simulator's status packet (ID {@code 0x62}), the answer to SIM_STAT: two empty strings kept
 * for older clients, status flags, the step timing and the robot's true pose.
 *
 * @param flags        status flags (bit 2: the odometry has simulated error)
 * @param simInterval  simulated ms per step
 * @param realInterval real ms per step it aims for
 * @param lastInterval real ms the last step took
 * @param x            true x, mm
 * @param y            true y, mm
 * @param z            true z, mm
 * @param th           true heading, degrees
 */
public record SimStat(long flags, int simInterval, int realInterval, int lastInterval, int x, int y, int z, int th) {
    /** Flag bit: the simulator adds error to the odometry. */
    public static final int ODOMETRY_ERROR = 0x04;

    /** @return the packet */
    public PioneerPacket toPacket() {
        return new PacketBuilder(Commands.SIMSTAT_PACKET).string("").string("").i32((int) flags)
                .u16(simInterval).u16(realInterval).u16(lastInterval).i32(x).i32(y).i32(z).i32(th)
                .i32(0).i32(0).i32(0).i32(0).build();
    }

    /**
     * @param p a packet with ID {@code 0x62}
     * @return the status
     * @throws PacketFormatException if it is not one or ends early
     */
    public static SimStat decode(PioneerPacket p) {
        if (p.id() != Commands.SIMSTAT_PACKET) {
            throw new PacketFormatException("packet " + p.id() + " is not a SIMSTAT packet (0x62)");
        }
        PacketData d = p.reader("SIMSTAT packet");
        d.string("old field 1");
        d.string("old field 2");
        long flags = d.i32("flags") & 0xffffffffL;
        return new SimStat(flags, d.u16("sim interval"), d.u16("real interval"), d.u16("last interval"),
                d.i32("x"), d.i32("y"), d.i32("z"), d.i32("th"));
    }
}
