package robosim.examples.goldfinder;

import robosim.aria.ArHeatSensor;
import robosim.aria.ArRobot;

/**
 * What a Gold robot's heat sensor (a 360° view, three cells' reach) tells it of the gold, which
 * glows with heat: whether the gold is near enough to count as found, the cell it places the gold
 * in, and the side of the robot's cell that faces the heat. Heat passes through walls, so the
 * sensor says where the gold is, not how to get there.
 */
final class HeatGuide {
    private final ArRobot robot;
    private final ArHeatSensor heat;
    private final double cellSize;
    private final MazeKnowledge map;
    private final Course course;

    /**
     * @param robot    the robot
     * @param heat     its heat sensor, attached
     * @param cellSize the maze's cell size, mm
     * @param map      its map
     * @param course   where it stands
     */
    HeatGuide(ArRobot robot, ArHeatSensor heat, double cellSize, MazeKnowledge map, Course course) {
        this.robot = robot;
        this.heat = heat;
        this.cellSize = cellSize;
        this.map = map;
        this.course = course;
    }

    /** @return whether the sensor places the gold within {@code distance} mm */
    boolean placesGoldWithin(double distance) {
        return heat.senses() && heat.getDistance() <= distance;
    }

    /**
     * The cell where the heat sensor places the gold, or -1 while it senses no heat. (A robot can
     * know a cell from afar, read with its laser: the heat brings it there.)
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

    /**
     * The side towards the gold's heat, if the heat is sensed through an open side onto a cell
     * nobody has sensed; else -1. (Heat passes through walls: a known cell towards it may lead
     * nowhere near the gold.)
     *
     * @return the side, 0 to 3, or -1
     */
    int sideTowardsHeat() {
        if (!heat.senses()) {
            return -1;
        }
        int d = Math.floorMod((int) Math.round((robot.getTh() + heat.getBearing()) / 90), 4);
        int x = course.x();
        int y = course.y();
        return map.open(x, y, d) && !map.isSensed(x + Directions.dx(d), y + Directions.dy(d)) ? d : -1;
    }
}
