/**
 * The Pioneer Robot-Object: an ARIA-style API ({@link robosim.aria.ArRobot},
 * {@link robosim.aria.ArPose}, {@link robosim.aria.ArUtil}) over RoboSim's hardware simulator, and
 * ARIA's map of the world a robot runs in ({@link robosim.aria.ArMap}).
 */
package robosim.aria;
