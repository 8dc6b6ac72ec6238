package robosim.hw.sip;

import robosim.params.ConversionFactors;

/**
 * What a connection's {@link SipPart}s are made from.
 *
 * @param factors       the robot's conversion factors
 * @param sonarCount    its sonar ring's size
 * @param sonarMaxRange what a sonar reads before its first reading, mm
 */
public record SipContext(ConversionFactors factors, int sonarCount, double sonarMaxRange) {
}
