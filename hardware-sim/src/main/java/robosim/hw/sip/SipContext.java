package robosim.hw.sip;

import robosim.params.ConversionFactors;

/**
 * What a connection's {@link SipPart}s are made from.
 *
 * @param factors       the robot's conversion factors
 * @param sonarCount    its sonar ring's size
 * @param sonarMaxRange what a sonar reads before its first reading, mm
 * @param gripper       whether the robot has a gripper on the general IO port (the CONFIG reply's
 *                      gripper flag, on the client's side), so that ANPORT's high byte is its switches
 */
public record SipContext(ConversionFactors factors, int sonarCount, double sonarMaxRange, boolean gripper) {
    /**
     * A context without a gripper.
     *
     * @param factors       the robot's conversion factors
     * @param sonarCount    its sonar ring's size
     * @param sonarMaxRange what a sonar reads before its first reading, mm
     */
    public SipContext(ConversionFactors factors, int sonarCount, double sonarMaxRange) {
        this(factors, sonarCount, sonarMaxRange, false);
    }
}
