/**
 * GoldFinder: a team of Pioneers searches a maze for gold by their sensors alone, and tells each
 * other what it found. Start with {@link robosim.examples.goldfinder.Gold}, the robot and its loop;
 * each part of what it does is a class of one job:
 *
 * <ul>
 *   <li>{@code TeamTalk}: the team messages ({@link robosim.examples.goldfinder.MazeMessage}), what
 *       a robot tells and what it hears;</li>
 *   <li>{@code SearchPhases}: the search a step at a time: note the cell it is in, sense, commit to
 *       the next cell when it must, drive; back off; done;</li>
 *   <li>{@code Survey} and {@code WallSensing}: what a robot senses of the cells with its laser,
 *       driving or standing, and its sonars at the start;</li>
 *   <li>{@code MazeKnowledge}: the map of cells it believes, and where its teammates are and go;</li>
 *   <li>{@code Wayfinder} and {@code TeamPlan}: the frontier it claims, the side it leaves a cell
 *       by, and how it gives way to teammates;</li>
 *   <li>{@code HeatGuide}: what its heat sensor says of the gold;</li>
 *   <li>{@code Track} and {@code Driving}: the line through its committed cells, bends taken as
 *       arcs, and how it drives it (steering, speed, stopping short of a teammate, backing off);</li>
 *   <li>{@code Course}: where it is, the cells it has committed to, and where it goes;</li>
 *   <li>{@code TeamDrawings}: the drawing of what it believes, for viewers;</li>
 *   <li>{@code Directions}: the numbering of a cell's four sides.</li>
 * </ul>
 *
 * {@link robosim.examples.goldfinder.GoldFinder} starts one robot the original's way, or a team as
 * threads. The mazes they search are made by the Environment's maze generator ({@code
 * robosim.env.world.maze}, run by {@code bin/robosim maze}); of a maze, a robot is told only its
 * cell size, by the world's {@code cellSize} property.
 */
package robosim.examples.goldfinder;
