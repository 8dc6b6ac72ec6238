package robosim.protocol;

/**
 * What a robot learns about itself at the start of a step: the responses to its requests of the
 * previous step.
 *
 * @param step       the step these values are the result of (0 before the first step)
 * @param timeMs     simulated time at the end of that step
 * @param x          odometry x in mm
 * @param y          odometry y in mm
 * @param th         odometry heading in degrees, in (-180, 180]
 * @param vel        translational velocity in mm/s
 * @param rotVel     rotational velocity in deg/s
 * @param leftVel    left wheel velocity in mm/s
 * @param rightVel   right wheel velocity in mm/s
 * @param stalled    whether the last motion was stopped by a collision
 * @param sonar      range in mm of each sonar transducer, by index
 * @param collisions collisions counted since the start
 */
public record RobotState(long step, long timeMs, double x, double y, double th, double vel, double rotVel,
                         double leftVel, double rightVel, boolean stalled, int[] sonar, int collisions) {
}
