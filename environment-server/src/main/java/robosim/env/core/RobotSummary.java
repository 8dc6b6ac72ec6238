package robosim.env.core;

/**
 * A robot at the end of a run (or at any moment), with the figures the Environment counts for every
 * robot, whatever its program reports.
 *
 * @param name             the robot
 * @param x                true x, mm
 * @param y                true y, mm
 * @param th               true heading, degrees
 * @param distance         distance travelled, mm
 * @param collisions       collisions counted
 * @param stalled          whether it is stalled now
 * @param odoX             odometry x, mm: where the robot believes it is
 * @param odoY             odometry y, mm
 * @param odoTh            odometry heading, degrees
 * @param stalls           how many times it became stalled (its stall flag went up; staying stalled
 *                         counts once). The core counts a collision at each, so today it equals
 *                         {@code collisions}
 * @param messagesSent     the messages it sent that the CommunicationsSystem accepted
 * @param messagesLost     the copies of its messages dropped on the way to a robot whose program was
 *                         connected: out of range, behind a wall, or lost by chance (a broadcast that
 *                         misses two robots counts two)
 * @param messagesReceived the messages delivered to it
 */
public record RobotSummary(String name, double x, double y, double th, double distance, int collisions,
                           boolean stalled, double odoX, double odoY, double odoTh, int stalls, long messagesSent,
                           long messagesLost, long messagesReceived) {
}
