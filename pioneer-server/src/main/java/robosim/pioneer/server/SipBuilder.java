package robosim.pioneer.server;

import robosim.hw.sip.SipContext;
import robosim.hw.sip.SipFields;
import robosim.hw.sip.SipParts;
import robosim.params.ConversionFactors;
import robosim.pioneer.Sip;
import robosim.protocol.GripperState;
import robosim.protocol.RobotState;

/**
 * Makes each step's status packet from the robot's state, in the robot's units: positions divided
 * by the DistConvFactor (15 bits that wrap), the heading by the AngleConvFactor, wheel velocities
 * by the VelConvFactor; the state's parts that a SIP carries (the sonar ring, the bumpers, the
 * battery, the gripper's switches) are written by their {@link SipParts}. A state without a battery reads 13.0 V, as
 * MobileSim's does. Safe to use from the robot's thread and the thread that sends the SIPs of a
 * robot standing by.
 */
final class SipBuilder {
    /** The battery of a state that has none, decivolts: MobileSim's. */
    static final int BATTERY = 130;

    /**
     * ANPORT of a robot with a gripper whose state does not carry it yet (before the Environment's
     * welcome): the gripper as it starts, deployed (paddles open, lift down, nothing triggered).
     */
    static final int GRIPPER_DEPLOYED = (GripperState.LEFT_PADDLE_CLEAR | GripperState.RIGHT_PADDLE_CLEAR) << 8;

    private final ConversionFactors factors;
    private final SipParts parts;
    private final boolean gripper;

    /**
     * @param factors the robot's conversion factors
     */
    SipBuilder(ConversionFactors factors) {
        this(factors, false);
    }

    /**
     * @param factors the robot's conversion factors
     * @param gripper whether the robot has a gripper
     */
    SipBuilder(ConversionFactors factors, boolean gripper) {
        this.factors = factors;
        this.parts = new SipParts(new SipContext(factors, 0, 0));
        this.gripper = gripper;
    }

    /**
     * @param state         the robot's state after a step
     * @param frame         its odometry frame
     * @param motorsEnabled whether the client has enabled the motors
     * @param sonarOn       whether the sonar is on
     * @return the SIP
     */
    Sip build(RobotState state, OdometryFrame frame, boolean motorsEnabled, boolean sonarOn) {
        return build(state, frame, motorsEnabled, sonarOn, false);
    }

    /**
     * The SIP of a robot standing where the state puts it, while the run does not step: the state's
     * pose, sonar and bumpers, velocities zero.
     *
     * @param state         the robot's latest state
     * @param frame         its odometry frame
     * @param motorsEnabled whether the client has enabled the motors
     * @param sonarOn       whether the sonar is on
     * @return the SIP
     */
    Sip standing(RobotState state, OdometryFrame frame, boolean motorsEnabled, boolean sonarOn) {
        return build(state, frame, motorsEnabled, sonarOn, true);
    }

    private synchronized Sip build(RobotState state, OdometryFrame frame, boolean motorsEnabled, boolean sonarOn,
                                   boolean standing) {
        double[] pose = frame.toRobot(state.x(), state.y(), state.th());
        int x = (int) Math.round(pose[0] / factors.distConvFactor());
        int y = (int) Math.round(pose[1] / factors.distConvFactor());
        int th = (int) Math.round(Math.toRadians(pose[2]) / factors.angleConvFactor());
        int left = standing ? 0 : (int) Math.round(state.leftVel() / factors.velConvFactor());
        int right = standing ? 0 : (int) Math.round(state.rightVel() / factors.velConvFactor());
        SipFields f = new SipFields((motorsEnabled ? Sip.FLAG_MOTORS : 0) | (sonarOn ? Sip.FLAG_SONARS : 0),
                state.stalled() ? Sip.LEFT_STALL | Sip.RIGHT_STALL : 0, BATTERY);
        if (gripper && state.get(GripperState.PART) == null) {
            f.anPort = GRIPPER_DEPLOYED;
        }
        parts.write(state, f);
        boolean moving = !standing && (state.vel() != 0 || state.rotVel() != 0);
        int rotVel = standing ? 0 : (int) Math.round(state.rotVel() * 10);
        return new Sip(moving, x, y, th, left, right, f.battery, f.stallBump, 0, f.flags, 0, f.sonar, f.anPort, 0xff, 0xff,
                f.batteryX10, 0, rotVel, 0, 0, -127, f.stateOfCharge);
    }
}
