package robosim.protocol;

import java.util.List;

/**
 * Robot states for tests, with fewer fields than {@link RobotState}'s own constructors take: what a
 * test leaves out is empty, 0 or null (no gripper, no camera, every sonar reading new, the motors'
 * state unknown).
 */
public final class RobotStates {
    private RobotStates() {
    }

    /**
     * A state with laser and heat readings but no messages, errors, bumper contacts or true pose.
     *
     * @param step       the step
     * @param timeMs     simulated time, ms
     * @param x          odometry x, mm
     * @param y          odometry y, mm
     * @param th         odometry heading, degrees
     * @param vel        mm/s
     * @param rotVel     deg/s
     * @param leftVel    mm/s
     * @param rightVel   mm/s
     * @param stalled    whether stalled
     * @param sonar      sonar ranges, mm
     * @param collisions collisions so far
     * @param laser      laser scan, mm
     * @param heat       heat reading or null
     * @return the state
     */
    public static RobotState of(long step, long timeMs, double x, double y, double th, double vel, double rotVel,
                                double leftVel, double rightVel, boolean stalled, int[] sonar, int collisions,
                                int[] laser, HeatReading heat) {
        return of(step, timeMs, x, y, th, vel, rotVel, leftVel, rightVel, stalled, sonar, collisions, laser, heat,
                List.of(), List.of(), 0);
    }

    /**
     * A state with messages, errors and bumper contacts but no true pose.
     *
     * @param step       the step
     * @param timeMs     simulated time, ms
     * @param x          odometry x, mm
     * @param y          odometry y, mm
     * @param th         odometry heading, degrees
     * @param vel        mm/s
     * @param rotVel     deg/s
     * @param leftVel    mm/s
     * @param rightVel   mm/s
     * @param stalled    whether stalled
     * @param sonar      sonar ranges, mm
     * @param collisions collisions so far
     * @param laser      laser scan, mm
     * @param heat       heat reading or null
     * @param messages   messages delivered
     * @param errors     request errors
     * @param bumpers    bumper contacts
     * @return the state
     */
    public static RobotState of(long step, long timeMs, double x, double y, double th, double vel, double rotVel,
                                double leftVel, double rightVel, boolean stalled, int[] sonar, int collisions,
                                int[] laser, HeatReading heat, List<MessageDelivery> messages, List<String> errors,
                                int bumpers) {
        return new RobotState(step, timeMs, x, y, th, vel, rotVel, leftVel, rightVel, stalled, sonar, collisions,
                laser, heat, messages, errors, bumpers, null, null, null, null, null);
    }
}
