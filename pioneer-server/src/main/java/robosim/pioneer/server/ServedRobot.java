package robosim.pioneer.server;

import robosim.params.ConversionFactors;
import robosim.protocol.RobotParameters;

/**
 * A robot of the world as its Pioneer port serves it.
 *
 * @param name       its name in the world
 * @param robotType  its type, for the Environment's hello (for example {@code pioneer})
 * @param parameters its parameters (its body, limits, sensors; its class and subclass answer SYNC2)
 * @param factors    its conversion factors, for the status packets
 */
public record ServedRobot(String name, String robotType, RobotParameters parameters, ConversionFactors factors) {
}
