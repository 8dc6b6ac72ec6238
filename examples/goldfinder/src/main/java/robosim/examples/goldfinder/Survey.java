package robosim.examples.goldfinder;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import robosim.aria.ArRobot;
import robosim.aria.ArSick;

/**
 * What a Gold robot senses of the maze with its own sensors: the walls of the cell it stands in,
 * and of the cells straight ahead that its laser can read ({@link WallSensing} does the reading).
 * What it senses goes into its map, and into the list of its own cells, in the order sensed: the
 * cells its reports repeat to the team and its drawing fills in.
 */
final class Survey {
    private final ArRobot robot;
    private final ArSick laser;
    private final double cellSize;
    private final MazeKnowledge map;
    private final Course course;
    /** The cells this robot sensed itself, in order: column, row, open sides. */
    private final List<int[]> ownCells = new ArrayList<>();

    /**
     * @param robot    the robot
     * @param laser    its laser, switched on
     * @param cellSize the maze's cell size, mm
     * @param map      its map, which what it senses joins
     * @param course   where it stands
     */
    Survey(ArRobot robot, ArSick laser, double cellSize, MazeKnowledge map, Course course) {
        this.robot = robot;
        this.laser = laser;
        this.cellSize = cellSize;
        this.map = map;
        this.course = course;
    }

    /** @return the cells this robot sensed itself, in the order it sensed them: column, row, open sides */
    List<int[]> ownCells() {
        return Collections.unmodifiableList(ownCells);
    }

    /** Senses the walls of the cell the robot stands in, unless somebody has sensed them already. */
    void senseHereIfNew() {
        if (map.isSensed(course.x(), course.y())) {
            return;
        }
        int open = WallSensing.openSides(robot, laser, cellSize);
        map.sensed(course.x(), course.y(), open);
        ownCells.add(new int[] {course.x(), course.y(), open});
    }

    /**
     * Reads the cells straight ahead with the laser ({@link WallSensing#cellsAhead}), so that a
     * corridor is driven through in one move instead of a stop in every cell.
     *
     * @return how many cells it sensed that nobody had
     */
    int lookAhead() {
        int d = Math.floorMod((int) Math.round(robot.getTh() / 90), 4);
        int[] ahead = WallSensing.cellsAhead(robot, laser, cellSize);
        int added = 0;
        for (int j = 0; j < ahead.length; j++) {
            int x = course.x() + (j + 1) * Directions.dx(d);
            int y = course.y() + (j + 1) * Directions.dy(d);
            if (!map.isSensed(x, y)) {
                map.sensed(x, y, ahead[j]);
                ownCells.add(new int[] {x, y, ahead[j]});
                added++;
            }
        }
        return added;
    }
}
