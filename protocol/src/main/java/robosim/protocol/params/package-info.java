/**
 * Robot parameter files: the record that travels to the Environment, the readers of ARIA's
 * {@code .p} form and of the original RoboSim's XML form, and {@link
 * robosim.protocol.params.RobotParametersReader}, which picks one by the file's extension.
 */
package robosim.protocol.params;
