/** ARIA's gotoActionExample: a Pioneer driving a square by setting each corner as a goto action's goal. */
package robosim.examples.gotoaction;
