package robosim.hw.sip;

import robosim.pioneer.Sip;
import robosim.protocol.GripperState;
import robosim.protocol.RobotState;
import robosim.protocol.StateParts;

/**
 * The gripper's switches in SIPs, as ARIA's ArGripper.cpp reads a gripper on the general IO port
 * ({@code GENIO}, what a Pioneer's gripper packet names as type 2): the high byte of ANPORT
 * ({@code getAnalogPortSelected() >> 8}), with the bits of {@link GripperState}. A robot without a
 * gripper leaves ANPORT 0.
 *
 * <p>Read back on a client whose server said it has a gripper, the switches are exact; how far the
 * paddles are closed and the lift raised is what the switches tell: the paddles 1 when both are
 * triggered, 0 when open, 0.5 between; the lift 0 at either limit (the switch does not say which)
 * and 0.5 between (a SIP carries no position); the grasp time is not in a SIP and reads 0; the held object
 * is not known (−1).
 */
final class GripperInSip implements SipPart {
    private final boolean gripper;

    GripperInSip(SipContext context) {
        this.gripper = context.gripper();
    }

    @Override
    public void write(RobotState state, SipFields sip) {
        GripperState g = state.get(GripperState.PART);
        if (g != null) {
            sip.anPort = g.switches() << 8;
        }
    }

    @Override
    public StateParts read(Sip sip, StateParts parts) {
        if (!gripper) {
            return parts;
        }
        int d = (sip.anPort() >> 8) & 0xff;
        boolean left = (d & GripperState.LEFT_PADDLE_CLEAR) == 0;
        boolean right = (d & GripperState.RIGHT_PADDLE_CLEAR) == 0;
        double paddles = left && right ? 1 : (d & GripperState.PADDLES_OPEN_CLEAR) == 0 ? 0 : 0.5;
        double lift = (d & GripperState.LIFT_LIMIT_CLEAR) == 0 ? 0 : 0.5;
        return parts.with(GripperState.PART, new GripperState(d, 0, paddles, lift, -1));
    }
}
