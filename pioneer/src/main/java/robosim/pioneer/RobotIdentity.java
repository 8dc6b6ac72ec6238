package robosim.pioneer;

/**
 * Who the robot is, as the server's answer to SYNC2 says: its name, class and subclass. ARIA loads
 * the parameter file named after the subclass.
 *
 * @param name       the robot's name ({@code MobileSim} tells ARIA that the robot is simulated)
 * @param robotClass its class, for example {@code Pioneer}
 * @param subclass   its subclass, for example {@code p3dx}
 */
public record RobotIdentity(String name, String robotClass, String subclass) {
    /** @return the SYNC2 answer: ID 2 and three NUL-terminated strings */
    public PioneerPacket toPacket() {
        return new PacketBuilder(Commands.SYNC2).string(name).string(robotClass).string(subclass).build();
    }

    /**
     * @param p the SYNC2 answer
     * @return the identity it gives
     * @throws PacketFormatException if it is not one
     */
    public static RobotIdentity decode(PioneerPacket p) {
        if (p.id() != Commands.SYNC2) {
            throw new PacketFormatException("packet " + p.id() + " is not the answer to SYNC2");
        }
        PacketData d = p.reader("SYNC2 answer");
        return new RobotIdentity(d.string("name"), d.string("class"), d.string("subclass"));
    }
}
