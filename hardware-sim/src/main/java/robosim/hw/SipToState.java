package robosim.hw;

import java.util.List;
import robosim.hw.sip.SipContext;
import robosim.hw.sip.SipParts;
import robosim.params.ConversionFactors;
import robosim.pioneer.LaserPacket;
import robosim.pioneer.Sip;
import robosim.pioneer.SimStat;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotState;
import robosim.protocol.StateParts;
import robosim.protocol.TruePose;

/**
 * Turns a Pioneer robot server's packets into the robot's states, as ARIA's
 * {@code ArRobot::processMotorPacket} reads them: the position from the first SIP times the
 * DistConvFactor, then moved by each SIP's difference from the one before (the 15-bit counters
 * wrap, so a jump of more than 0x1000 units is a wrap); the heading times the AngleConvFactor;
 * the wheel velocities times the VelConvFactor; the parts of the state a SIP carries (the sonar
 * ring, the bumpers, the battery, the gripper's switches) are read by their {@link SipParts}. Laser packets are gathered into whole
 * scans, SIMSTAT packets give the true pose; the SIP's flags bit 0 says whether the motors are enabled
 * (ARIA's {@code areMotorsEnabled}). The odometry is the server's own: (0, 0, 0) where a
 * simulator put it at the connection, wherever a real Pioneer's counters stood. No sockets: the
 * link feeds it.
 */
final class SipToState {
    /** ARIA's threshold for a wrap of the 15-bit position counters. */
    private static final int WRAP = 0x1000;
    private static final int RANGE = 0x8000;
    private static final int[] NONE = new int[0];

    private final ConversionFactors factors;
    private final SipParts parts;
    private boolean first = true;
    private int lastX;
    private int lastY;
    private double x;
    private double y;
    private boolean wasStalled;
    private int collisions;
    private int[] laser = NONE;
    private int[] building;
    private int built;
    private TruePose truePose;

    /**
     * @param factors     the robot's conversion factors
     * @param sonarCount  the sonar ring's size, from the robot's parameter file
     * @param sonarMaxRange what a sonar reads before its first reading, mm
     * @param gripper     whether the server said the robot has a gripper (its CONFIG reply)
     */
    SipToState(ConversionFactors factors, int sonarCount, double sonarMaxRange, boolean gripper) {
        this.factors = factors;
        this.parts = new SipParts(new SipContext(factors, sonarCount, sonarMaxRange, gripper));
    }

    /**
     * @param sip    a status packet
     * @param step   the step it becomes: one per SIP
     * @param timeMs ms since the link opened
     * @param errors what was wrong with the robot's requests since the last state
     * @return the robot's state
     */
    synchronized RobotState state(Sip sip, long step, long timeMs, List<String> errors) {
        if (first) {
            first = false;
            x = sip.xPos() * factors.distConvFactor();
            y = sip.yPos() * factors.distConvFactor();
        } else {
            x += unwrap(sip.xPos() - lastX) * factors.distConvFactor();
            y += unwrap(sip.yPos() - lastY) * factors.distConvFactor();
        }
        lastX = sip.xPos();
        lastY = sip.yPos();
        double th = fix(Math.toDegrees(sip.th() * factors.angleConvFactor()));
        double left = sip.leftVel() * factors.velConvFactor();
        double right = sip.rightVel() * factors.velConvFactor();
        // firmware that reports the rotation says it; otherwise ARIA works it out from the wheels
        double rotVel = sip.rotVelX10() != 0 ? sip.rotVelX10() / 10.0
                : Math.toDegrees((right - left) / 2 * factors.diffConvFactor());
        boolean stalled = (sip.stallBump() & (Sip.LEFT_STALL | Sip.RIGHT_STALL)) != 0;
        if (stalled && !wasStalled) {
            collisions++;
        }
        wasStalled = stalled;
        StateParts read = parts.read(sip, StateParts.NONE)
                .with(LaserReading.PART, laser.length == 0 ? null : new LaserReading(laser.clone()))
                .with(TruePose.PART, truePose);
        return new RobotState(step, timeMs, x, y, th, (left + right) / 2, rotVel, left, right, stalled, collisions,
                List.of(), errors, (sip.flags() & Sip.FLAG_MOTORS) != 0, read);
    }

    /**
     * Gathers a laser packet: when it completes a scan, the scan becomes the states' laser.
     *
     * @param p a 0x60 or 0x61 packet
     */
    synchronized void laser(LaserPacket p) {
        if (p.first() == 0 || building == null || building.length != p.total() || p.first() != built) {
            building = new int[p.total()];
            built = 0;
            if (p.first() != 0) {
                return; // the start of this scan was missed: wait for the next
            }
        }
        int[] ranges = p.ranges();
        System.arraycopy(ranges, 0, building, p.first(), ranges.length);
        built = p.first() + ranges.length;
        if (built == building.length) {
            laser = building;
            building = null;
        }
    }

    /** The laser is off: states carry no scan. */
    synchronized void laserOff() {
        laser = NONE;
        building = null;
    }

    /** @param s a SIMSTAT packet: its true pose goes into the states until {@link #trueOff()} */
    synchronized void simStat(SimStat s) {
        truePose = new TruePose(s.x(), s.y(), s.th());
    }

    /** The true pose is no longer asked for. */
    synchronized void trueOff() {
        truePose = null;
    }

    private static int unwrap(int delta) {
        if (delta > WRAP) {
            return delta - RANGE;
        }
        return delta < -WRAP ? delta + RANGE : delta;
    }

    static double fix(double degrees) {
        double a = Math.IEEEremainder(degrees, 360);
        return a <= -180 ? a + 360 : a;
    }
}
