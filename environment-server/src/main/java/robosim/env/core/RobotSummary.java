package robosim.env.core;

/**
 * A robot at the end of a run (or at any moment).
 *
 * @param name       the robot
 * @param x          true x, mm
 * @param y          true y, mm
 * @param th         true heading, degrees
 * @param distance   distance travelled, mm
 * @param collisions collisions counted
 * @param stalled    whether it is stalled now
 * @param odoX       odometry x, mm: where the robot believes it is
 * @param odoY       odometry y, mm
 * @param odoTh      odometry heading, degrees
 */
public record RobotSummary(String name, double x, double y, double th, double distance, int collisions,
                           boolean stalled, double odoX, double odoY, double odoTh) {
}
