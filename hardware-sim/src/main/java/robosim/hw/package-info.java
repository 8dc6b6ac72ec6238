/**
 * The generic robot package: what every Robot-Object shares ({@link robosim.hw.AbstractRobot}),
 * and the {@link robosim.hw.HardwareSimulator} thread that carries its requests and responses to
 * and from the Environment in lockstep.
 */
package robosim.hw;
