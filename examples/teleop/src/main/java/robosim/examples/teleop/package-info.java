/** A Pioneer driven from the keyboard: one command a line on standard input. */
package robosim.examples.teleop;
