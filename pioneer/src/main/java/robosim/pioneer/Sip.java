package robosim.pioneer;

import java.util.ArrayList;
import java.util.List;

/**
 * The server's standard status packet (SIP), ID {@code 0x32} (stopped) or {@code 0x33} (moving),
 * in the robot's units: the values as they go on the wire, before the client's conversion
 * factors. The optional fields that follow the sonar readings are always written, in the order
 * ARIA reads them.
 *
 * @param moving       whether the ID is {@code 0x33}
 * @param xPos         x, 15 bits that wrap, × DistConvFactor → mm
 * @param yPos         y, as xPos
 * @param th           heading, × AngleConvFactor → radians
 * @param leftVel      left wheel, × VelConvFactor → mm/s
 * @param rightVel     right wheel, as leftVel
 * @param battery      decivolts, 0 to 255
 * @param stallBump    bit 0 left stall, bit 8 right stall, bits 1–7 and 9–15 bumpers
 * @param control      the heading setpoint, in the heading's units
 * @param flags        bit 0 motors on, bits 1–4 sonar arrays on, bit 5 e-stop
 * @param compass      degrees / 2
 * @param sonar        the sonar readings this SIP carries
 * @param anPort       ANPORT, two bytes: ARIA's {@code getAnalogPortSelected()}; a gripper on the
 *                     general IO port puts its switch byte in the high byte (ARIA's ArGripper.cpp
 *                     reads {@code getAnalogPortSelected() >> 8} for a GENIO gripper)
 * @param digIn        the digital inputs
 * @param digOut       the digital outputs
 * @param batteryX10   the battery in tenths of a volt, two bytes
 * @param chargeState  0 not charging
 * @param rotVelX10    the rotational velocity in tenths of a degree per second
 * @param faultFlags   the controller's fault flags
 * @param latVel       lateral velocity, mm/s
 * @param temperature  degrees Celsius, −127 for none
 * @param stateOfCharge percent, 0 for none
 */
public record Sip(boolean moving, int xPos, int yPos, int th, int leftVel, int rightVel, int battery,
                  int stallBump, int control, int flags, int compass, List<SonarReading> sonar, int anPort,
                  int digIn, int digOut, int batteryX10, int chargeState, int rotVelX10, int faultFlags,
                  int latVel, int temperature, int stateOfCharge) {

    /** FLAGS bit: the motors are enabled. */
    public static final int FLAG_MOTORS = 0x01;
    /** FLAGS bits: the four sonar arrays are on. */
    public static final int FLAG_SONARS = 0x1E;
    /** FLAGS bit: the emergency stop is pressed. */
    public static final int FLAG_ESTOP = 0x20;
    /** STALLBUMP bit: the left wheel is stalled. */
    public static final int LEFT_STALL = 0x0001;
    /** STALLBUMP bit: the right wheel is stalled. */
    public static final int RIGHT_STALL = 0x0100;

    /**
     * One sonar reading of a SIP.
     *
     * @param index the transducer's number
     * @param range the range, × RangeConvFactor → mm
     */
    public record SonarReading(int index, int range) {
    }

    /** Copies the readings so the record stays immutable. */
    public Sip {
        sonar = List.copyOf(sonar);
    }

    /**
     * A SIP whose ANPORT is 0 (no gripper on the general IO port).
     *
     * @param moving        whether the ID is {@code 0x33}
     * @param xPos          x
     * @param yPos          y
     * @param th            heading
     * @param leftVel       left wheel
     * @param rightVel      right wheel
     * @param battery       decivolts
     * @param stallBump     stall and bumper bits
     * @param control       the heading setpoint
     * @param flags         the flags
     * @param compass       degrees / 2
     * @param sonar         the sonar readings
     * @param digIn         the digital inputs
     * @param digOut        the digital outputs
     * @param batteryX10    the battery in tenths of a volt
     * @param chargeState   0 not charging
     * @param rotVelX10     tenths of a degree per second
     * @param faultFlags    the fault flags
     * @param latVel        lateral velocity
     * @param temperature   degrees Celsius
     * @param stateOfCharge percent
     */
    public Sip(boolean moving, int xPos, int yPos, int th, int leftVel, int rightVel, int battery, int stallBump,
               int control, int flags, int compass, List<SonarReading> sonar, int digIn, int digOut, int batteryX10,
               int chargeState, int rotVelX10, int faultFlags, int latVel, int temperature, int stateOfCharge) {
        this(moving, xPos, yPos, th, leftVel, rightVel, battery, stallBump, control, flags, compass, sonar, 0, digIn,
                digOut, batteryX10, chargeState, rotVelX10, faultFlags, latVel, temperature, stateOfCharge);
    }

    /** @return the packet */
    public PioneerPacket toPacket() {
        PacketBuilder b = new PacketBuilder(moving ? Commands.SIP_MOVING : Commands.SIP_STOPPED)
                .u16(xPos & 0x7fff).u16(yPos & 0x7fff).i16(th).i16(leftVel).i16(rightVel).u8(battery)
                .u16(stallBump).i16(control).u16(flags).u8(compass).u8(sonar.size());
        for (SonarReading r : sonar) {
            b.u8(r.index()).u16(Math.min(r.range(), 0xffff));
        }
        return b.u16(anPort & 0xffff).u8(0).u8(digIn).u8(digOut).u16(batteryX10).u8(chargeState).i16(rotVelX10)
                .u16(faultFlags).i16(latVel).u8(temperature).u8(stateOfCharge).build();
    }

    /**
     * Reads a SIP as ARIA's {@code ArRobot::processMotorPacket} does: the optional fields each only
     * when bytes remain.
     *
     * @param p a packet with ID {@code 0x32} or {@code 0x33}
     * @return the SIP
     * @throws PacketFormatException if it is not a SIP or ends inside a required field
     */
    public static Sip decode(PioneerPacket p) {
        if (p.id() != Commands.SIP_STOPPED && p.id() != Commands.SIP_MOVING) {
            throw new PacketFormatException("packet " + p.id() + " is not a SIP (0x32 or 0x33)");
        }
        PacketData d = p.reader("SIP");
        int x = d.u16("XPOS") & 0x7fff;
        int y = d.u16("YPOS") & 0x7fff;
        int th = d.i16("TH");
        int lvel = d.i16("LVEL");
        int rvel = d.i16("RVEL");
        int battery = d.u8("BATTERY");
        int stall = d.u16("STALLBUMP");
        int control = d.i16("CONTROL");
        int flags = d.u16("FLAGS");
        int compass = d.u8("COMPASS");
        int n = d.u8("NSONAR");
        List<SonarReading> sonar = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            sonar.add(new SonarReading(d.u8("sonar number"), d.u16("sonar range")));
        }
        int anPort = 0;
        int digIn = 0;
        int digOut = 0;
        if (d.remaining() > 0) {
            anPort = d.u16("ANPORT");
            d.u8("ANALOG");
            digIn = d.u8("DIGIN");
            digOut = d.u8("DIGOUT");
        }
        int battX10 = d.remaining() > 0 ? d.u16("BATTX10") : battery;
        int charge = d.remaining() > 0 ? d.u8("CHARGESTATE") : 0;
        int rotVel = d.remaining() > 0 ? d.i16("ROTVEL") : 0;
        int faults = d.remaining() > 0 ? d.u16("FAULTFLAGS") : 0;
        int lat = d.remaining() > 0 ? d.i16("LATVEL") : 0;
        int temp = d.remaining() > 0 ? d.i8("TEMP") : -127;
        int soc = d.remaining() > 0 ? d.u8("SOC") : 0;
        return new Sip(p.id() == Commands.SIP_MOVING, x, y, th, lvel, rvel, battery, stall, control, flags, compass,
                sonar, anPort, digIn, digOut, battX10, charge, rotVel, faults, lat, temp, soc);
    }
}
