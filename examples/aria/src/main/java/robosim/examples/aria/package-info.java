/**
 * ARIA's example programs (AriaCoda's {@code examples/}) ported to Java, one class per program with
 * the C++'s structure and output, connecting with ARIA's connector idiom ({@link
 * robosim.aria.Aria}, {@link robosim.aria.ArArgumentParser}, {@link robosim.aria.ArRobotConnector}):
 * each runs against a RoboSim Environment ({@code NAME HOST PORT}), RoboSim's Pioneer port or
 * MobileSim ({@code -remoteHost HOST -remoteRobotTcpPort PORT}).
 */
package robosim.examples.aria;
