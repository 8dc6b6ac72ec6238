package robosim.examples.goldfinder;

import java.util.Arrays;
import robosim.aria.ArMath;
import robosim.aria.ArRobot;
import robosim.aria.ArSick;

/**
 * Tells which sides of the cell a robot stands in are open, from its range sensors alone: the
 * laser for the sides ahead and to the left and right, the rear sonars for the side behind. A side
 * is open when the nearest echo that way lies farther than {@value #OPEN_FRACTION} of a cell from
 * the robot's centre: a wall on the cell's edge echoes from half a cell, anything beyond an open
 * side (a far wall, a teammate standing in the next cell) from farther than that.
 */
final class WallSensing {
    static final double OPEN_FRACTION = 0.6;

    private WallSensing() {
    }

    /**
     * @param robot    a robot standing still at a cell centre, facing along a grid axis
     * @param laser    its laser, switched on
     * @param cellSize mm
     * @return bit d set when side d (0 east, 1 north, 2 west, 3 south) is open
     */
    static int openSides(ArRobot robot, ArSick laser, double cellSize) {
        int[] scan = laser.getRawScan();
        double increment = scan.length > 1 ? 180.0 / (scan.length - 1) : 1;
        double laserX = robot.getParameters().laserX();
        int open = 0;
        for (int d = 0; d < 4; d++) {
            double a = ArMath.fixAngle(d * 90 - robot.getTh());
            double reach;
            if (Math.abs(a) <= 91 && scan.length > 0) {
                int i = (int) Math.round((Math.max(-90, Math.min(90, a)) + 90) / increment);
                reach = scan[i] + laserX * Math.cos(Math.toRadians(a));
            } else {
                reach = rearReach(robot);
            }
            if (reach > OPEN_FRACTION * cellSize) {
                open |= 1 << d;
            }
        }
        return open;
    }

    /**
     * The farthest cell ahead that {@link #cellsAhead} reads: two cells, so that every cell a Gold
     * robot reads from afar lies within its heat sensor's reach (three cells), and a cell holding
     * the gold is never known without the gold being sensed.
     */
    static final int MOST_AHEAD = 2;

    /**
     * Reads the cells straight ahead of a robot standing at a cell's centre and facing along a grid
     * axis, from its laser alone: the beam straight ahead tells how far the corridor runs, and for
     * each cell the beams aimed at the middles of its side walls tell whether those sides are open
     * (an open side lets the beam on into the next cell, at least a quarter of a cell farther). It
     * stops at the first cell whose far side is closed, after {@value #MOST_AHEAD} cells, or where
     * something nearer than a wall (a teammate) hides what lies beyond.
     *
     * @param robot    a robot standing still at a cell centre, facing along a grid axis
     * @param laser    its laser, switched on
     * @param cellSize mm
     * @return the open sides of the cells ahead, nearest first (as {@link #openSides}); possibly none
     */
    static int[] cellsAhead(ArRobot robot, ArSick laser, double cellSize) {
        int[] scan = laser.getRawScan();
        if (scan.length < 3) {
            return new int[0];
        }
        double increment = 180.0 / (scan.length - 1);
        double laserX = robot.getParameters().laserX();
        int d = Math.floorMod((int) Math.round(robot.getTh() / 90), 4);
        double off = ArMath.fixAngle(robot.getTh() - d * 90);
        double ahead = reach(scan, increment, laserX, -off);
        double side = cellSize / 2 - WALL_HALF;
        int[] out = new int[MOST_AHEAD];
        int cells = 0;
        for (int j = 1; j <= MOST_AHEAD; j++) {
            if (ahead < (j + 0.5) * cellSize - cellSize / 4) {
                break; // something stands in this cell or before it
            }
            int open = 1 << ((d + 2) % 4);
            if (ahead > (j + 0.5) * cellSize + cellSize / 4) {
                open |= 1 << d;
            }
            double wall = Math.hypot(j * cellSize, side);
            double angle = Math.toDegrees(Math.atan2(side, j * cellSize));
            double left = reach(scan, increment, laserX, angle - off);
            double right = reach(scan, increment, laserX, -angle - off);
            if (left < wall - cellSize / 8 || right < wall - cellSize / 8) {
                break; // a side wall is hidden: this cell cannot be read from here
            }
            if (left > wall + cellSize / 4) {
                open |= 1 << ((d + 1) % 4);
            }
            if (right > wall + cellSize / 4) {
                open |= 1 << ((d + 3) % 4);
            }
            out[cells++] = open;
            if ((open & (1 << d)) == 0) {
                break;
            }
        }
        return Arrays.copyOf(out, cells);
    }

    /** Half a maze wall's thickness, mm: walls are 100 mm thick, centred on the grid lines. */
    private static final double WALL_HALF = 50;

    /** The range at a bearing (degrees, left positive), measured from the robot's centre. */
    private static double reach(int[] scan, double increment, double laserX, double bearing) {
        if (Math.abs(bearing) > 90) {
            return 0;
        }
        int i = (int) Math.round((bearing + 90) / increment);
        return scan[i] + laserX * Math.cos(Math.toRadians(bearing));
    }

    /** The nearest echo behind the robot, measured from its centre. */
    private static double rearReach(ArRobot robot) {
        int best = robot.getClosestSonarNumber(150, -150);
        if (best < 0) {
            return 0;
        }
        var reading = robot.getSonarReading(best);
        return reading.getRange() - reading.getSensorX();
    }
}
