/**
 * Serves the robots of a world to ARIA programs over the Pioneer protocol, as MobileSim does on
 * ports 8101, 8102, ...: {@link robosim.pioneer.server.PioneerPorts} opens one port per robot; an
 * ARIA client's handshake and commands are taken by a {@link robosim.pioneer.server.PioneerSession};
 * the robot itself is a {@link robosim.pioneer.server.BridgeRobot}, an ordinary robot client of the
 * Environment with its own HardwareSimulator, which turns the client's commands into requests and
 * each step's state into a status packet (and laser packets), paced in real time while a client is
 * attached, since ARIA keeps wall-clock time.
 *
 * <p>The translation is plain code without I/O: {@link robosim.pioneer.server.CommandHandler}
 * (commands in), {@link robosim.pioneer.server.SipBuilder} and
 * {@link robosim.pioneer.server.LaserScan} (packets out), in the robot's own odometry frame
 * ({@link robosim.pioneer.server.OdometryFrame}).
 */
package robosim.pioneer.server;
