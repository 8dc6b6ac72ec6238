package robosim.examples.goldfinder;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import robosim.aria.ArMath;
import robosim.aria.ArRobot;
import robosim.aria.ArSick;

/**
 * What a Gold robot senses of the maze with its own sensors, every step, driving or standing: the
 * sides of the cells around it that its laser reads ({@link WallSensing#side}), and the sides it
 * drives through (open, as it went through them). A cell joins its map once all four of its sides
 * are known, by it or its teammates, and the robot stands where it would feel the gold's heat if
 * the gold lay there: the cell's centre within its heat sensor's reach and in its laser's clear
 * view. So a cell known from afar never hides the gold. What it senses also goes into the list of
 * its own cells, in the order sensed: the cells its reports repeat to the team and its drawing
 * fills in.
 */
final class Survey {
    /** How many cells around its own it reads, each way. */
    private static final int AROUND = 3;

    private final ArRobot robot;
    private final ArSick laser;
    private final double cellSize;
    private final double heatReach;
    private final MazeKnowledge map;
    private final Course course;
    /** The sides it has sensed itself, by {@link #sideKey}: open or not. */
    private final Map<Long, Boolean> sides = new HashMap<>();
    /** The cells this robot sensed itself, in order: column, row, open sides. */
    private final List<int[]> ownCells = new ArrayList<>();

    /**
     * @param robot     the robot
     * @param laser     its laser, switched on
     * @param cellSize  the maze's cell size, mm
     * @param heatReach how far its heat sensor feels the gold, mm
     * @param map       its map, which what it senses joins
     * @param course    where it stands
     */
    Survey(ArRobot robot, ArSick laser, double cellSize, double heatReach, MazeKnowledge map, Course course) {
        this.robot = robot;
        this.laser = laser;
        this.cellSize = cellSize;
        this.heatReach = heatReach;
        this.map = map;
        this.course = course;
    }

    /** @return the cells this robot sensed itself, in the order it sensed them: column, row, open sides */
    List<int[]> ownCells() {
        return Collections.unmodifiableList(ownCells);
    }

    /**
     * Senses the walls of the cell the robot stands in at its centre, facing along a grid axis,
     * unless somebody has already: the sides not yet known with its laser and rear sonars ({@link
     * WallSensing#openSides}), which read the sides beside and behind it too.
     */
    void senseHereStanding() {
        int x = course.x();
        int y = course.y();
        if (map.isSensed(x, y)) {
            return;
        }
        int standing = WallSensing.openSides(robot, laser, cellSize);
        int open = 0;
        for (int d = 0; d < 4; d++) {
            int known = known(x, y, d);
            boolean isOpen = known == WallSensing.UNSEEN ? (standing & (1 << d)) != 0 : known == WallSensing.OPEN;
            sides.put(sideKey(x, y, d), isOpen);
            open |= isOpen ? 1 << d : 0;
        }
        add(x, y, open);
    }

    /** The robot came into its cell through side {@code entry} of it: that side is open. */
    void cameThrough(int entry) {
        sides.put(sideKey(course.x(), course.y(), entry), true);
    }

    /**
     * Reads with the laser the unknown sides of the cells around the robot, and adds to the map
     * every cell whose sides are now all known and that the robot sees as it would the gold.
     *
     * @return how many cells it added
     */
    int sense() {
        int[] scan = laser.getRawScan();
        int added = 0;
        for (int x = course.x() - AROUND; x <= course.x() + AROUND; x++) {
            for (int y = course.y() - AROUND; y <= course.y() + AROUND; y++) {
                if (map.isSensed(x, y)) {
                    continue;
                }
                int open = 0;
                boolean all = true;
                for (int d = 0; d < 4; d++) {
                    int known = known(x, y, d);
                    if (known == WallSensing.UNSEEN) {
                        known = WallSensing.side(robot, scan, cellSize, x, y, d);
                        if (known != WallSensing.UNSEEN) {
                            sides.put(sideKey(x, y, d), known == WallSensing.OPEN);
                        }
                    }
                    all &= known != WallSensing.UNSEEN;
                    open |= known == WallSensing.OPEN ? 1 << d : 0;
                }
                if (all && wouldFeelGoldIn(x, y, scan)) {
                    add(x, y, open);
                    added++;
                }
            }
        }
        return added;
    }

    /** What is known of side d of cell (x, y): from this robot's own readings, or from the map's neighbour. */
    private int known(int x, int y, int d) {
        Boolean mine = sides.get(sideKey(x, y, d));
        int nx = x + Directions.dx(d);
        int ny = y + Directions.dy(d);
        if (map.isSensed(nx, ny)) {
            return map.open(nx, ny, (d + 2) % 4) || Boolean.TRUE.equals(mine) ? WallSensing.OPEN : WallSensing.CLOSED;
        }
        return mine == null ? WallSensing.UNSEEN : mine ? WallSensing.OPEN : WallSensing.CLOSED;
    }

    /**
     * Whether the heat sensor would feel gold lying at the cell's centre: within its reach (with a
     * margin), and either the robot is in the cell or its laser sees clear to the centre.
     */
    private boolean wouldFeelGoldIn(int x, int y, int[] scan) {
        double cx = (x + 0.5) * cellSize;
        double cy = (y + 0.5) * cellSize;
        double d = Math.hypot(cx - robot.getX(), cy - robot.getY());
        if (d > heatReach - 300) {
            return false;
        }
        if (x == course.x() && y == course.y()) {
            return true;
        }
        if (scan.length < 3) {
            return false;
        }
        double th = robot.getTh();
        double lx = robot.getX() + robot.getParameters().laserX() * Math.cos(Math.toRadians(th));
        double ly = robot.getY() + robot.getParameters().laserX() * Math.sin(Math.toRadians(th));
        double bearing = ArMath.fixAngle(Math.toDegrees(Math.atan2(cy - ly, cx - lx)) - th);
        if (Math.abs(bearing) > 89) {
            return false;
        }
        int i = (int) Math.round((bearing + 90) / (180.0 / (scan.length - 1)));
        return scan[i] >= Math.hypot(cx - lx, cy - ly) - 100;
    }

    private void add(int x, int y, int open) {
        map.sensed(x, y, open);
        ownCells.add(new int[] {x, y, open});
    }

    /** One key for a side, whichever of its two cells names it: by the cell to its west or south. */
    static long sideKey(int x, int y, int d) {
        int cx = d == 2 ? x - 1 : x;
        int cy = d == 3 ? y - 1 : y;
        return MazeKnowledge.key(cx, cy) * 2 + (d % 2);
    }
}
