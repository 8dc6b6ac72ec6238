package robosim.protocol;

/**
 * One sonar transducer's mounting pose in the robot frame (x forward, y left).
 *
 * @param index the transducer number, from 0
 * @param x     mm forward of the robot centre
 * @param y     mm left of the robot centre
 * @param th    heading of the transducer in degrees, counter-clockwise from forward
 */
public record SonarUnit(int index, double x, double y, double th) {
}
