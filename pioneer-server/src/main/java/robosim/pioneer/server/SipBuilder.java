package robosim.pioneer.server;

import java.util.ArrayList;
import java.util.List;
import robosim.params.ConversionFactors;
import robosim.pioneer.Sip;
import robosim.protocol.RobotState;

/**
 * Makes each step's status packet from the robot's state, in the robot's units: positions divided
 * by the DistConvFactor (15 bits that wrap), the heading by the AngleConvFactor, wheel velocities
 * by the VelConvFactor, sonar ranges by the RangeConvFactor. At most 16 sonar readings go in one
 * SIP, cycling through the ring as MobileSim does, so a ring of more than 16 takes several SIPs.
 * The battery reads 13.0 V, as MobileSim's does. Safe to use from the robot's thread and the
 * thread that sends the SIPs of a robot standing by.
 */
final class SipBuilder {
    /** The most sonar readings one SIP carries. */
    static final int MAX_SONAR_PER_SIP = 16;
    /** The battery, decivolts. */
    static final int BATTERY = 130;

    private final ConversionFactors factors;
    private int nextSonar;

    /**
     * @param factors the robot's conversion factors
     */
    SipBuilder(ConversionFactors factors) {
        this.factors = factors;
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
        int stallBump = (state.stalled() ? Sip.LEFT_STALL | Sip.RIGHT_STALL : 0) | bumperBits(state.bumpers());
        int flags = (motorsEnabled ? Sip.FLAG_MOTORS : 0) | (sonarOn ? Sip.FLAG_SONARS : 0);
        boolean moving = !standing && (state.vel() != 0 || state.rotVel() != 0);
        int rotVel = standing ? 0 : (int) Math.round(state.rotVel() * 10);
        return new Sip(moving, x, y, th, left, right, BATTERY, stallBump, 0, flags, 0,
                sonarOn ? sonar(state.sonar()) : List.of(), 0xff, 0xff, BATTERY, 0, rotVel, 0, 0, -127, 0);
    }

    private List<Sip.SonarReading> sonar(int[] ranges) {
        List<Sip.SonarReading> out = new ArrayList<>();
        if (ranges.length == 0) {
            return out;
        }
        if (nextSonar >= ranges.length) {
            nextSonar = 0;
        }
        int n = Math.min(MAX_SONAR_PER_SIP, ranges.length - nextSonar);
        for (int i = nextSonar; i < nextSonar + n; i++) {
            out.add(new Sip.SonarReading(i, (int) Math.round(ranges[i] / factors.rangeConvFactor())));
        }
        nextSonar = (nextSonar + n) % ranges.length;
        return out;
    }

    /**
     * The bumper ring's six 60° sectors as a Pioneer's STALLBUMP bits: the front bumpers in bits
     * 1 to 5 of the low byte, from the left (sector 1, front-left: bits 1 and 2; sector 0, ahead:
     * bit 3; sector 5, front-right: bits 4 and 5); the rear in bits 1 to 5 of the high byte in the
     * same way from the rear-right (sector 4), behind (sector 3) to the rear-left (sector 2).
     */
    static int bumperBits(int sectors) {
        int bits = 0;
        bits |= (sectors & 1 << 1) != 0 ? 1 << 1 | 1 << 2 : 0;
        bits |= (sectors & 1) != 0 ? 1 << 3 : 0;
        bits |= (sectors & 1 << 5) != 0 ? 1 << 4 | 1 << 5 : 0;
        bits |= (sectors & 1 << 4) != 0 ? (1 << 1 | 1 << 2) << 8 : 0;
        bits |= (sectors & 1 << 3) != 0 ? 1 << 3 << 8 : 0;
        bits |= (sectors & 1 << 2) != 0 ? (1 << 4 | 1 << 5) << 8 : 0;
        return bits;
    }
}
