/**
 * GoldFinder: a team of Pioneers searches a maze for gold by their sensors alone. Each {@link
 * robosim.examples.goldfinder.Gold} robot reads walls with its laser and sonars ({@code WallSensing}),
 * keeps what it and its teammates sensed ({@code MazeKnowledge}), claims the nearest frontier no
 * nearer teammate has claimed ({@code TeamPlan}) and tells its team by {@link
 * robosim.examples.goldfinder.MazeMessage}; {@link robosim.examples.goldfinder.GoldFinder} starts
 * one robot the original's way or a team as threads. The mazes they search are made by the
 * Environment's maze generator ({@code robosim.env.world.maze}, run by {@code bin/robosim maze});
 * of a maze, a robot is told only its cell size, by the world's {@code cellSize} property.
 */
package robosim.examples.goldfinder;
