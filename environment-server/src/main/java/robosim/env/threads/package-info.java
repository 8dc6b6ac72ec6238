/**
 * The Environment's thread pools: {@link robosim.env.threads.PooledParallel}, the simulation's
 * parallel loop on a fixed pool of workers, which the server hands the simulation to read its robots'
 * sensors and to encode their time steps.
 */
package robosim.env.threads;
