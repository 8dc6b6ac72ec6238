/** A Pioneer that follows the wall on its right by its laser. */
package robosim.examples.wallfollower;
