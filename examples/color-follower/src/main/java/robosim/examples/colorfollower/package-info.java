/** ARIA's actsColorFollowingExample: a Pioneer with a VC-C4 camera that chases the largest blob of a colour. */
package robosim.examples.colorfollower;
