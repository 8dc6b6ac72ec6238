/** Two Pioneers that tell each other where they are over the Environment's comms, and meet. */
package robosim.examples.meetup;
