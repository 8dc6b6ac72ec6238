/**
 * The GeometryClient: RoboSim's world as JTS polygons, with swept collision detection and exact
 * ray and sonar-cone ranges. Pure code: no I/O, no clock, no threads.
 */
package robosim.geometry;
