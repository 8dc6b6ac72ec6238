/** ARIA's gripperExample: a Pioneer's gripper worked from the keyboard, one command a line. */
package robosim.examples.gripper;
