package robosim.pioneer.server;

import robosim.pioneer.GripperPacket;
import robosim.protocol.GripperState;
import robosim.protocol.RobotState;

/**
 * The gripper packets ({@code 0xE0}) an ARIA client asked for with GRIPPERPACREQUEST: 0 none, 1 one,
 * 2 one with every status packet, as a Pioneer's firmware sends them. ARIA's
 * {@code ArGripper::connectHandler} asks for them (2) to learn the gripper's type and stops them (0)
 * once the first comes (ArGripper.cpp, {@code packetHandler}); a gripper of type
 * {@link GripperPacket#GENERAL_IO} is then read from the SIPs. A robot with a gripper answers
 * {@link GripperPacket#GENERAL_IO}, its switches and grasp time, as soon as a state of the robot
 * carries its gripper; a robot without one answers {@link GripperPacket#NONE}, so that ARIA knows it
 * has none. Set by the client's thread and read by the robot's: its methods hold its lock.
 */
final class GripperReports {
    private final boolean hasGripper;
    private int mode;

    /**
     * @param hasGripper whether the robot's parameters give it a gripper
     */
    GripperReports(boolean hasGripper) {
        this.hasGripper = hasGripper;
    }

    /** @param mode 0 no packets, 1 one, 2 one every status packet */
    synchronized void request(int mode) {
        this.mode = mode;
    }

    /**
     * @param state the robot's state that the status packet of this cycle reports
     * @return the gripper packet to send after it, or null when none is due (none asked for, or the
     *         state does not carry the robot's gripper yet)
     */
    synchronized GripperPacket next(RobotState state) {
        if (mode == 0) {
            return null;
        }
        GripperPacket p;
        if (!hasGripper) {
            p = new GripperPacket(GripperPacket.NONE, 0, 0);
        } else {
            GripperState g = state.get(GripperState.PART);
            if (g == null) {
                return null;
            }
            p = new GripperPacket(GripperPacket.GENERAL_IO, g.switches(), g.graspTime());
        }
        if (mode == 1) {
            mode = 0;
        }
        return p;
    }
}
