package robosim.remote;

import robosim.protocol.RobotParameters;

/**
 * The bounds of the speed sliders, from the robot's parameter file ({@code MaxVelocity},
 * {@code MaxRVelocity}), and where they start: a walking pace, as ARIA's keyboard teleop starts
 * (its {@code ArModeTeleop} drives at most 400 mm/s), never above the robot's own limits.
 *
 * @param maxVel    the translational slider's top, mm/s
 * @param maxRotVel the rotational slider's top, deg/s
 * @param vel       the translational slider's start, mm/s
 * @param rotVel    the rotational slider's start, deg/s
 */
public record SpeedLimits(int maxVel, int maxRotVel, int vel, int rotVel) {
    /** Where the translational slider starts when the robot allows it, mm/s. */
    public static final int START_VEL = 300;
    /** Where the rotational slider starts when the robot allows it, deg/s. */
    public static final int START_ROT_VEL = 30;

    /**
     * @param p the robot's parameters
     * @return the sliders' bounds and starts
     */
    public static SpeedLimits of(RobotParameters p) {
        int maxVel = (int) Math.floor(p.maxVelocity());
        int maxRot = (int) Math.floor(p.maxRVelocity());
        return new SpeedLimits(maxVel, maxRot, Math.min(START_VEL, maxVel), Math.min(START_ROT_VEL, maxRot));
    }

    /** @param v a translational speed @return it within 0 and the top */
    public int clampVel(int v) {
        return Math.max(0, Math.min(maxVel, v));
    }

    /** @param v a rotational speed @return it within 0 and the top */
    public int clampRotVel(int v) {
        return Math.max(0, Math.min(maxRotVel, v));
    }
}
