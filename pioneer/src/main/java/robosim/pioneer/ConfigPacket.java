package robosim.pioneer;

/**
 * The server's configuration reply (ID {@code 0x20}) to CONFIG, with the fields in the order ARIA's
 * {@code ArRobotConfigPacketReader} reads them. Fields a simulator has no use for are written as 0.
 * The serial number {@code SIM} tells ARIA that the robot is simulated (it then reads the laser
 * from the robot's own connection).
 *
 * @param robotClass   the robot's class, for example {@code Pioneer}
 * @param subclass     its subclass, for example {@code p3dx}
 * @param serial       the serial number; {@code SIM} for a simulator
 * @param rotVelTop    the highest rotational velocity that may be set, degrees/s
 * @param transVelTop  the highest translational velocity that may be set, mm/s
 * @param rotAccelTop  the highest rotational acceleration, degrees/s²
 * @param transAccelTop the highest translational acceleration, mm/s²
 * @param name         the robot's name
 * @param sipCycle     ms between SIPs
 * @param hasGripper   whether a gripper is fitted
 * @param frontSonar   whether the front sonar array is fitted
 * @param rearSonar    whether the rear sonar array is fitted
 * @param watchdog     ms without a packet after which the robot stops
 * @param rotVelMax    the current maximum rotational velocity, degrees/s
 * @param transVelMax  the current maximum translational velocity, mm/s
 * @param rotAccel     the current rotational acceleration, degrees/s²
 * @param rotDecel     the current rotational deceleration, degrees/s²
 * @param transAccel   the current translational acceleration, mm/s²
 * @param transDecel   the current translational deceleration, mm/s²
 * @param frontBumps   front bumper segments
 * @param rearBumps    rear bumper segments
 * @param firmware     the firmware version
 */
public record ConfigPacket(String robotClass, String subclass, String serial, int rotVelTop, int transVelTop,
                           int rotAccelTop, int transAccelTop, String name, int sipCycle, boolean hasGripper,
                           boolean frontSonar, boolean rearSonar, int watchdog, int rotVelMax, int transVelMax,
                           int rotAccel, int rotDecel, int transAccel, int transDecel, int frontBumps,
                           int rearBumps, String firmware) {

    /** @return the packet */
    public PioneerPacket toPacket() {
        return new PacketBuilder(Commands.CONFIG_PACKET)
                .string(robotClass).string(subclass).string(serial).u8(0)
                .u16(rotVelTop).u16(transVelTop).u16(rotAccelTop).u16(transAccelTop).u16(400)
                .string(name).u8(sipCycle).u8(0).u8(0)
                .u16(hasGripper ? 1 : 0).u16(frontSonar ? 1 : 0).u8(rearSonar ? 1 : 0)
                .u16(0).u16(0).u16(watchdog).u8(0).u16(0).u16(0).u16(0).u16(0)
                .u16(rotVelMax).u16(transVelMax).u16(rotAccel).u16(rotDecel).u16(0).u16(0).u16(0)
                .u16(transAccel).u16(transDecel).u16(0).u16(0).u16(0)
                .u8(frontBumps).u8(rearBumps).u8(0).u8(0).u8(2).u8(0).u16(0).u8(0).u8(0).u16(0).u16(0)
                .string(firmware).u16(0).u16(0).u8(0)
                .u16(0).u16(0).u16(0).u16(0).u16(0).u16(0)
                .build();
    }

    /**
     * Reads a configuration reply as ARIA does, as far as its firmware version.
     *
     * @param p a packet with ID {@code 0x20}
     * @return the reply
     * @throws PacketFormatException if it is not one or ends early
     */
    public static ConfigPacket decode(PioneerPacket p) {
        if (p.id() != Commands.CONFIG_PACKET) {
            throw new PacketFormatException("packet " + p.id() + " is not a CONFIG reply (0x20)");
        }
        PacketData d = p.reader("CONFIG reply");
        String type = d.string("type");
        String subtype = d.string("subtype");
        String serial = d.string("serial number");
        d.u8("4mots");
        int rotVelTop = d.u16("RotVelTop");
        int transVelTop = d.u16("TransVelTop");
        int rotAccTop = d.u16("RotAccTop");
        int transAccTop = d.u16("TransAccTop");
        d.u16("PwmMax");
        String name = d.string("name");
        int sipCycle = d.u8("SipCycle");
        d.u8("HostBaud");
        d.u8("Aux1Baud");
        boolean gripper = d.u16("HasGripper") != 0;
        boolean front = d.u16("FrontSonar") != 0;
        boolean rear = d.u8("RearSonar") != 0;
        d.u16("LowBattery");
        d.u16("RevCount");
        int watchdog = d.u16("Watchdog");
        d.u8("NormalMPacs");
        d.u16("StallVal");
        d.u16("StallCount");
        d.u16("JoyVel");
        d.u16("JoyRVel");
        int rotVelMax = d.u16("RotVelMax");
        int transVelMax = d.u16("TransVelMax");
        int rotAcc = d.u16("RotAcc");
        int rotDecel = d.u16("RotDecel");
        d.u16("RotKP");
        d.u16("RotKV");
        d.u16("RotKI");
        int transAcc = d.u16("TransAcc");
        int transDecel = d.u16("TransDecel");
        d.u16("TransKP");
        d.u16("TransKV");
        d.u16("TransKI");
        int frontBumps = d.u8("FrontBumps");
        int rearBumps = d.u8("RearBumps");
        d.u8("Charger");
        d.u8("SonarCycle");
        d.u8("ResetBaud");
        d.u8("HasGyro");
        d.u16("DriftFactor");
        d.u8("Aux2Baud");
        d.u8("Aux3Baud");
        d.u16("TicksMM");
        d.u16("ShutdownVoltage");
        String firmware = d.remaining() > 0 ? d.string("firmware version") : "";
        return new ConfigPacket(type, subtype, serial, rotVelTop, transVelTop, rotAccTop, transAccTop, name, sipCycle,
                gripper, front, rear, watchdog, rotVelMax, transVelMax, rotAcc, rotDecel, transAcc, transDecel,
                frontBumps, rearBumps, firmware);
    }
}
