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
 * @param stepMs     the world's step length, ms: the SIP cycle a client is told, and is sent status
 *                   packets at, until the Environment's welcome gives the run's own
 */
public record ServedRobot(String name, String robotType, RobotParameters parameters, ConversionFactors factors,
                          int stepMs) {
    /**
     * @throws IllegalArgumentException naming the robot if the step length is not positive
     */
    public ServedRobot {
        if (stepMs <= 0) {
            throw new IllegalArgumentException(stepMs + " was supplied for robot " + name
                    + "'s step length: it must be above 0 ms");
        }
    }
}
