/** A Nomadic Scout program, written against the Nomad client calls, that wanders a world on its sonars. */
package robosim.examples.scoutwander;
