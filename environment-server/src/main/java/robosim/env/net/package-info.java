/**
 * The Environment's TCP layer: listening sockets for robots and viewers, one connection per peer,
 * and the lockstep loop that drives the {@link robosim.env.core.Simulation}.
 */
package robosim.env.net;
