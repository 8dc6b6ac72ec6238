package robosim.env.world.maze;

import robosim.env.core.Simulation;
import robosim.env.world.RobotSpec;
import robosim.env.world.World;
import robosim.protocol.RobotParameters;

/**
 * The steps a team that knew a maze would take to find its gold, stopping to turn in place at each
 * corner: the yardstick a searching team is measured against. Robots that take bends as arcs can
 * beat it, so it is not a true lower bound.
 */
public final class GoldBound {
    /** East, north, west, south, as {@link Maze#open} numbers them. */
    private static final int[][] DIRECTIONS = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};

    private GoldBound() {
    }

    /**
     * The shortest path from the nearest robot's cell to the gold's, driven at the robot's top speed
     * and accelerations, straight along each corridor, turning in place at each corner, and ending
     * where the gold is {@value Simulation#GOLD_FOUND_DISTANCE} mm away (a find counts there).
     *
     * @param maze     the maze
     * @param world    its world, with the team's robots and the gold
     * @param cellSize mm
     * @return steps
     * @throws IllegalArgumentException if the world has no gold or no robots
     */
    public static long steps(Maze maze, World world, double cellSize) {
        if (world.gold() == null || world.robots().isEmpty()) {
            throw new IllegalArgumentException("world " + world.name() + " has no gold or no robots: a maze's"
                    + " lower bound needs both");
        }
        int gx = (int) Math.floor(world.gold().x() / cellSize);
        int gy = (int) Math.floor(world.gold().y() / cellSize);
        int[][] toGold = maze.distancesFrom(gx, gy);
        double best = Double.POSITIVE_INFINITY;
        for (RobotSpec r : world.robots()) {
            RobotParameters p = r.parameters();
            int x = (int) Math.floor(r.x() / cellSize);
            int y = (int) Math.floor(r.y() / cellSize);
            double seconds = 0;
            double run = 0;
            int heading = -1;
            while (toGold[x][y] > 0) {
                for (int d = 0; d < 4; d++) {
                    int nx = x + DIRECTIONS[d][0];
                    int ny = y + DIRECTIONS[d][1];
                    if (maze.open(x, y, d) && toGold[nx][ny] == toGold[x][y] - 1) {
                        if (heading >= 0 && d != heading) {
                            seconds += ramp(run, p.maxVelocity(), p.transAccel()) + ramp(90, p.maxRVelocity(), p.rotAccel());
                            run = 0;
                        }
                        heading = d;
                        run += cellSize;
                        x = nx;
                        y = ny;
                        break;
                    }
                }
            }
            seconds += ramp(Math.max(0, run - Simulation.GOLD_FOUND_DISTANCE), p.maxVelocity(), p.transAccel());
            best = Math.min(best, seconds);
        }
        return (long) Math.ceil(best * 1000 / world.stepMs());
    }

    /** Seconds to cover a distance from rest to rest, accelerating and braking at {@code accel}, capped at {@code top}. */
    private static double ramp(double distance, double top, double accel) {
        return distance >= top * top / accel ? distance / top + top / accel : 2 * Math.sqrt(distance / accel);
    }
}
