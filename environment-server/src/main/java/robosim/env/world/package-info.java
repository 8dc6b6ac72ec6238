/**
 * The world model: the immutable {@link robosim.env.world.World} (its size, step length, obstacles, heat
 * sources and gold, sensor and odometry noise, how messages travel between robots, and the
 * {@link robosim.env.world.RobotSpec robots} that must connect before a run starts) that the simulation
 * core is built from, with the rectangle it covers ({@link robosim.env.world.Bounds}), a map's
 * {@link robosim.env.world.ForbiddenZone forbidden zones}, and the robots asked for on the command line
 * ({@link robosim.env.world.RobotToPlace}). How a world is read from its XML file is
 * {@code robosim.env.world.xml}'s concern, and from an ARIA map {@code robosim.env.world.map}'s.
 */
package robosim.env.world;
