/**
 * The world model: the immutable {@link robosim.env.world.World} (its size, step length, obstacles, heat
 * sources and gold, sensor and odometry noise, how messages travel between robots, and the
 * {@link robosim.env.world.RobotSpec robots} that must connect before a run starts) that the simulation
 * core is built from. How a world is read from its XML file is {@code robosim.env.world.xml}'s concern.
 */
package robosim.env.world;
