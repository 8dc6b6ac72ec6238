/**
 * Maze worlds: {@link robosim.env.world.maze.Maze} carves a perfect maze on a grid of cells from a
 * seed, and {@link robosim.env.world.maze.MazeWorldWriter} writes it as a world file (walls on the
 * grid lines, the cell size as a world property, robots at the start, the gold in the farthest
 * cell), as {@code bin/robosim maze} and the GoldFinder benchmark do. The same size and seed always
 * give the same file. Nothing here reads files or depends on the rest of the Environment.
 */
package robosim.env.world.maze;
