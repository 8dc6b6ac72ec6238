/**
 * The Pioneer Robot-Object: an ARIA-style API ({@link robosim.aria.ArRobot},
 * {@link robosim.aria.ArPose}, {@link robosim.aria.ArUtil}) over RoboSim's hardware simulator.
 */
package robosim.aria;
