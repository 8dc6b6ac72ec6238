/**
 * Benchmarks: step rate in the grid world over TCP, and the wire formats. Run them with
 * {@code bin/robosim bench}; the figures are kept in docs/BENCHMARKS.md.
 */
package robosim.bench;
