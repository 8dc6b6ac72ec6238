/**
 * Benchmarks: load-and-connect time and step rate in the grid world (over TCP and in the core
 * alone, with sonar or sonar and laser), the wire formats, the laser, GoldFinder. Run them with
 * {@code bin/robosim bench}; the figures are kept in docs/BENCHMARKS.md.
 */
package robosim.bench;
