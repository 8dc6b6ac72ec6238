/** The README's first robot program: a Pioneer that drives a square. */
package robosim.examples.square;
