package robosim.hw.sip;

import java.util.ArrayList;
import java.util.List;
import robosim.pioneer.Sip;

/**
 * The fields of a SIP being written that the state's parts fill in, in the robot's units; the
 * motion's fields are the writer's own. A part adds to what is there: the stall bits and the
 * bumper bits share {@link #stallBump}.
 */
public final class SipFields {
    /** FLAGS, as the writer set them before the parts write: whether the sonars are on, say. */
    public int flags;
    /** STALLBUMP: the stall bits, then the bumpers'. */
    public int stallBump;
    /** BATTERY, decivolts, one byte. */
    public int battery;
    /** BATTX10, decivolts, two bytes. */
    public int batteryX10;
    /** ANPORT, two bytes: a gripper's switches in the high byte, as ARIA reads a GENIO gripper. */
    public int anPort;
    /** SOC, percent; 0 for none. */
    public int stateOfCharge;
    /** The sonar readings the SIP carries. */
    public final List<Sip.SonarReading> sonar = new ArrayList<>();

    /**
     * @param flags     the SIP's flags
     * @param stallBump its stall bits
     * @param battery   the battery to report when no part says, decivolts
     */
    public SipFields(int flags, int stallBump, int battery) {
        this.flags = flags;
        this.stallBump = stallBump;
        this.battery = battery;
        this.batteryX10 = battery;
    }
}
