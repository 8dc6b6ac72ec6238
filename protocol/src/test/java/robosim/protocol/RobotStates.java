package robosim.protocol;

import java.util.List;

/**
 * Robot states for tests, made from the values older tests give: an empty sonar or laser array is
 * that sensor off, a null heat reading no heat sensor, 0 bumpers no contact.
 */
public final class RobotStates {
    private RobotStates() {
    }

    /**
     * A state with sonar, laser and heat readings but no messages, errors, bumper contacts or true pose.
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
     * @param sonar      sonar ranges, mm; empty for off
     * @param collisions collisions so far
     * @param laser      laser scan, mm; empty for off
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
     * @param sonar      sonar ranges, mm; empty for off
     * @param collisions collisions so far
     * @param laser      laser scan, mm; empty for off
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
        return new RobotState(step, timeMs, x, y, th, vel, rotVel, leftVel, rightVel, stalled, collisions, messages,
                errors, null, StateParts.NONE)
                .with(SonarReading.PART, sonar.length == 0 ? null : new SonarReading(sonar))
                .with(LaserReading.PART, laser.length == 0 ? null : new LaserReading(laser))
                .with(HeatReading.PART, heat)
                .with(Bumpers.PART, bumpers == 0 ? null : new Bumpers(bumpers));
    }

    /**
     * A state with only motion and sonar, as {@link RobotState}'s old short constructor made.
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
     * @param sonar      sonar ranges, mm; empty for off
     * @param collisions collisions so far
     * @return the state
     */
    public static RobotState of(long step, long timeMs, double x, double y, double th, double vel, double rotVel,
                                double leftVel, double rightVel, boolean stalled, int[] sonar, int collisions) {
        return new RobotState(step, timeMs, x, y, th, vel, rotVel, leftVel, rightVel, stalled, collisions)
                .with(SonarReading.PART, sonar.length == 0 ? null : new SonarReading(sonar));
    }
}
