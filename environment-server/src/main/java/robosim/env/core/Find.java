package robosim.env.core;

/**
 * A confirmed find of the world's gold.
 *
 * @param robot    the robot that found it
 * @param step     the step in which it reported it
 * @param distance its true distance from the gold then, mm
 */
public record Find(String robot, long step, double distance) {
}
