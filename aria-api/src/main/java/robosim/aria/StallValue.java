package robosim.aria;

import robosim.params.BumperParameters;
import robosim.protocol.Bumpers;
import robosim.protocol.RobotState;

/**
 * The Pioneer's two bytes of stall and bumper flags ({@link ArRobot#getStallValue()}), laid out as
 * ARIA reads them in {@code ArRobot.h} and {@code ArBumpers.cpp}: bit 0 the left motor's stall,
 * bits 1 to 7 the rear bumpers, bit 8 the right motor's stall, bits 9 to 15 the front bumpers.
 *
 * <p>RoboSim's body reports contacts in {@value Bumpers#SECTORS} sectors of 60°, sector 0
 * centred dead ahead, counting counter-clockwise ({@link Bumpers}). A bumper's flag is
 * set when the sector holding its centre has contact; bumper i of a ring of n is centred where
 * ARIA's {@code ArBumpers} places its readings with its default range of
 * {@value #ANGLE_RANGE}°: {@code 67.5 − (i + 0.5)·135/n} degrees for the front ring, 180° more for
 * the rear. With five bumpers a ring's centres lie at ±54°, ±27° and 0°, so a contact dead ahead
 * presses front bumpers 1, 2 and 3. A stall stops both wheels, so it sets both motor bits. A ring the
 * parameter file does not declare ({@code FrontBumpers false}) sets no flags.
 */
final class StallValue {
    /** The left motor's stall flag. */
    static final int LEFT_MOTOR = 1;
    /** The right motor's stall flag. */
    static final int RIGHT_MOTOR = 1 << 8;
    /** The degrees a ring of bumpers spans: ARIA's {@code ArBumpers} default. */
    static final double ANGLE_RANGE = 135;
    private static final int REAR_FIRST_BIT = 1;
    private static final int FRONT_FIRST_BIT = 9;

    private StallValue() {
    }

    /**
     * @param s       a cycle's state
     * @param bumpers the robot's bump rings
     * @return the stall value of that state
     */
    static int of(RobotState s, BumperParameters bumpers) {
        int v = s.stalled() ? LEFT_MOTOR | RIGHT_MOTOR : 0;
        if (bumpers.frontBumpers()) {
            v |= ring(s.get(Bumpers.PART).sectors(), bumpers.numFrontBumpers(), 0) << FRONT_FIRST_BIT;
        }
        if (bumpers.rearBumpers()) {
            v |= ring(s.get(Bumpers.PART).sectors(), bumpers.numRearBumpers(), 180) << REAR_FIRST_BIT;
        }
        return v;
    }

    /** @return one flag per bumper of the ring, bumper 0 in bit 0 */
    private static int ring(int sectors, int n, double turn) {
        int flags = 0;
        for (int i = 0; i < n; i++) {
            if ((sectors & 1 << sector(bumperAngle(i, n, ANGLE_RANGE) + turn)) != 0) {
                flags |= 1 << i;
            }
        }
        return flags;
    }

    /**
     * ARIA's {@code ArBumpers::addBumpToBuffer}: where bumper i of a front ring of n lies.
     *
     * @param i          the bumper
     * @param n          the ring's bumpers
     * @param angleRange the degrees the ring spans
     * @return its centre, degrees, robot-relative
     */
    static double bumperAngle(int i, int n, double angleRange) {
        double each = angleRange / n;
        return -(i * each + each / 2 - angleRange / 2);
    }

    /** @return the 60° sector holding a robot-relative direction */
    static int sector(double degrees) {
        return Math.floorMod((int) Math.floor((ArMath.fixAngle(degrees) + 30) / 60), Bumpers.SECTORS);
    }
}
