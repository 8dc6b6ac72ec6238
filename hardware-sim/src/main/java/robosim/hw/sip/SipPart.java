package robosim.hw.sip;

import robosim.pioneer.Sip;
import robosim.protocol.RobotState;
import robosim.protocol.StateParts;

/**
 * One part of a robot's state as a SIP carries it. A connection makes its own instance of each
 * (a part may remember what earlier SIPs carried, as a sonar ring larger than one SIP does), and
 * uses it one way: a Pioneer port only writes, a Pioneer link only reads.
 */
public interface SipPart {
    /**
     * The server's side: puts the state's part into the SIP being written.
     *
     * @param state the robot's state
     * @param sip   the SIP's fields
     */
    void write(RobotState state, SipFields sip);

    /**
     * The client's side: reads the part back from a SIP received.
     *
     * @param sip   the SIP
     * @param parts the state's parts so far
     * @return the parts with this one's, as far as the SIP tells it
     */
    StateParts read(Sip sip, StateParts parts);
}
