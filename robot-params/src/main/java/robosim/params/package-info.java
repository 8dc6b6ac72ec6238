/**
 * Robot parameter files: the readers of ARIA's {@code .p} form ({@link robosim.params.ParameterFileReader})
 * and of the XML forms (RoboSim's and the original RoboSim's layouts) ({@link robosim.params.XmlParameterFileReader}), with the rules
 * both share; {@link robosim.params.RobotParametersReader}, which picks one by the file's extension;
 * {@link robosim.params.RobotParameterFiles}, which finds a shipped file by name; and
 * {@link robosim.params.ConversionFactors}, a robot's ARIA conversion factors. What they read is a
 * {@link robosim.protocol.RobotParameters}, the record a robot sends to the Environment when it connects.
 */
package robosim.params;
