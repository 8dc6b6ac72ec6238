/**
 * The pan-tilt-zoom camera and ACTS colour-blob tracking: the camera's motion within its limits,
 * the image a camera sees of coloured shapes with heights, and the blobs ACTS finds in it. Pure
 * computation from arguments: no clock, no I/O.
 */
package robosim.env.camera;
