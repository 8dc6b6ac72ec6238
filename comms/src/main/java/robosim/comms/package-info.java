/**
 * The CommunicationsSystem: how messages travel between robots (point to point, multicast groups,
 * broadcast) under range, walls, latency, loss and size rules. Pure code, stepped by the
 * simulation core.
 */
package robosim.comms;
