package robosim.hw.sip;

import robosim.pioneer.Sip;
import robosim.protocol.Bumpers;
import robosim.protocol.RobotState;
import robosim.protocol.StateParts;

/**
 * The bumper ring's six 60° sectors as a Pioneer's STALLBUMP bits: the front bumpers in bits 1 to
 * 5 of the low byte, from the left (sector 1, front-left: bits 1 and 2; sector 0, ahead: bit 3;
 * sector 5, front-right: bits 4 and 5); the rear in bits 1 to 5 of the high byte in the same way
 * from the rear-right (sector 4), behind (sector 3) to the rear-left (sector 2). Read back, the
 * outer pairs of each byte are the sides.
 */
final class BumpersInSip implements SipPart {
    BumpersInSip(SipContext context) {
    }

    @Override
    public void write(RobotState state, SipFields sip) {
        sip.stallBump |= bits(state.get(Bumpers.PART).sectors());
    }

    @Override
    public StateParts read(Sip sip, StateParts parts) {
        return parts.with(Bumpers.PART, new Bumpers(sectors(sip.stallBump())));
    }

    /**
     * @param sectors the bumper ring's contacts
     * @return them as STALLBUMP bits
     */
    static int bits(int sectors) {
        int bits = 0;
        bits |= (sectors & 1 << 1) != 0 ? 1 << 1 | 1 << 2 : 0;
        bits |= (sectors & 1) != 0 ? 1 << 3 : 0;
        bits |= (sectors & 1 << 5) != 0 ? 1 << 4 | 1 << 5 : 0;
        bits |= (sectors & 1 << 4) != 0 ? (1 << 1 | 1 << 2) << 8 : 0;
        bits |= (sectors & 1 << 3) != 0 ? 1 << 3 << 8 : 0;
        bits |= (sectors & 1 << 2) != 0 ? (1 << 4 | 1 << 5) << 8 : 0;
        return bits;
    }

    /**
     * @param stallBump a SIP's STALLBUMP
     * @return its bumper bits as the ring's sectors
     */
    static int sectors(int stallBump) {
        int front = stallBump >> 1 & 0x1f;
        int rear = stallBump >> 9 & 0x1f;
        int sectors = 0;
        sectors |= (front & 0b00011) != 0 ? 1 << 1 : 0;
        sectors |= (front & 0b00100) != 0 ? 1 : 0;
        sectors |= (front & 0b11000) != 0 ? 1 << 5 : 0;
        sectors |= (rear & 0b00011) != 0 ? 1 << 4 : 0;
        sectors |= (rear & 0b00100) != 0 ? 1 << 3 : 0;
        sectors |= (rear & 0b11000) != 0 ? 1 << 2 : 0;
        return sectors;
    }
}
