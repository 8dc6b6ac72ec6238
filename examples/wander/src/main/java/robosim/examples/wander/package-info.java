/** A Pioneer program that wanders a world on its sonars alone. */
package robosim.examples.wander;
