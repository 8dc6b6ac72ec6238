package robosim.pioneer;

/**
 * The gripper's packet (ID {@code 0xE0}), the server's answer to GRIPPERPACREQUEST, as ARIA's
 * {@code ArGripper::packetHandler} (ArGripper.cpp) reads it: three unsigned bytes.
 *
 * @param type      how the gripper is wired: {@link #GENERAL_IO} or {@link #USER_IO}; any other value
 *                  (0) tells ARIA the robot has no gripper
 * @param switches  the gripper's switch byte (the bits of ARIA's {@code mySwitches}), 0 to 255
 * @param graspTime the grasp time, in 20 ms units, 0 to 255
 */
public record GripperPacket(int type, int switches, int graspTime) {
    /** The type of a robot without a gripper. */
    public static final int NONE = 0;
    /** The type of a gripper on the user IO port (ARIA's USERIO). */
    public static final int USER_IO = 1;
    /** The type of a gripper on the general IO port (ARIA's GENIO), as on a Pioneer 2 or 3. */
    public static final int GENERAL_IO = 2;

    /**
     * Checks the ranges.
     *
     * @throws IllegalArgumentException naming the field whose value is not a byte
     */
    public GripperPacket {
        check("type", type);
        check("switches", switches);
        check("graspTime", graspTime);
    }

    /** @return the packet */
    public PioneerPacket toPacket() {
        return new PacketBuilder(Commands.GRIPPER_PACKET).u8(type).u8(switches).u8(graspTime).build();
    }

    /**
     * @param p a packet with ID {@code 0xE0}
     * @return the gripper's packet
     * @throws PacketFormatException if it is not one or ends early
     */
    public static GripperPacket decode(PioneerPacket p) {
        if (p.id() != Commands.GRIPPER_PACKET) {
            throw new PacketFormatException("packet " + p.id() + " is not a gripper packet (0xE0)");
        }
        PacketData d = p.reader("gripper packet");
        return new GripperPacket(d.u8("type"), d.u8("switches"), d.u8("grasp time"));
    }

    private static void check(String name, int value) {
        if (value < 0 || value > 255) {
            throw new IllegalArgumentException(value + " was supplied for the gripper packet's " + name
                    + ": it is one unsigned byte, 0 to 255");
        }
    }
}
