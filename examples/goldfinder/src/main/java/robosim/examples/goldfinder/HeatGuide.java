package robosim.examples.goldfinder;

import robosim.aria.ArHeatSensor;
import robosim.aria.ArRobot;

/**
 * What a Gold robot's heat sensor (a 360° view, three cells' reach) tells it of the gold, which
 * glows with heat: whether the gold is near enough to count as found, and the cell it places the
 * gold in. Walls block heat, so the sensor feels the gold only in its line of sight: by then the
 * robot is a few cells from it (on the benchmark's mazes, some 20 to 50 steps before the find),
 * and telling the team where the heat comes from would gain them nothing.
 */
final class HeatGuide {
    private final ArRobot robot;
    private final ArHeatSensor heat;
    private final double cellSize;

    /**
     * @param robot    the robot
     * @param heat     its heat sensor, attached
     * @param cellSize the maze's cell size, mm
     */
    HeatGuide(ArRobot robot, ArHeatSensor heat, double cellSize) {
        this.robot = robot;
        this.heat = heat;
        this.cellSize = cellSize;
    }

    /** @return whether the sensor places the gold within {@code distance} mm */
    boolean placesGoldWithin(double distance) {
        return heat.senses() && heat.getDistance() <= distance;
    }

    /**
     * The cell where the heat sensor places the gold, or -1 while it senses no heat.
     *
     * @return the cell's key, or -1
     */
    long goldCell() {
        if (!heat.senses()) {
            return -1;
        }
        double bearing = Math.toRadians(robot.getTh() + heat.getBearing());
        double gx = robot.getX() + heat.getDistance() * Math.cos(bearing);
        double gy = robot.getY() + heat.getDistance() * Math.sin(bearing);
        return MazeKnowledge.key((int) Math.floor(gx / cellSize), (int) Math.floor(gy / cellSize));
    }
}
