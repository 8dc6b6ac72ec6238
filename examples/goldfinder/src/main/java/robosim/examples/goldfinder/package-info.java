/**
 * GoldFinder: a team of Pioneers searches a maze for gold by their sensors alone. Each {@link
 * robosim.examples.goldfinder.Gold} robot reads walls with its laser and sonars ({@code WallSensing}),
 * keeps what it and its teammates sensed ({@code MazeKnowledge}), claims the nearest frontier no
 * nearer teammate has claimed ({@code TeamPlan}) and tells its team by {@link
 * robosim.examples.goldfinder.MazeMessage}; {@link robosim.examples.goldfinder.GoldFinder} starts
 * one robot the original's way or a team as threads; and the maze generator makes its worlds.
 */
package robosim.examples.goldfinder;
