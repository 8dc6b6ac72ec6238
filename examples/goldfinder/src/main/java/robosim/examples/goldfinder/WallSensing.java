package robosim.examples.goldfinder;

import robosim.aria.ArMath;
import robosim.aria.ArRobot;
import robosim.aria.ArSick;

/**
 * Tells which sides of the maze's cells are open, from a robot's range sensors alone. Standing at
 * its starting cell's centre ({@link #openSides}) it reads the sides ahead and to the left and
 * right with its laser and the side behind with its rear sonars: a side is open when the nearest
 * echo that way lies farther than {@value #OPEN_FRACTION} of a cell from the robot's centre (a
 * wall on the cell's edge echoes from half a cell, anything beyond an open side, a far wall or a
 * teammate standing in the next cell, from farther than that). Anywhere else, driving or standing,
 * it reads any side in its laser's view ({@link #side}).
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

    /** What the laser says of a side of a cell: it saw no way to tell. */
    static final int UNSEEN = -1;
    /** What the laser says of a side of a cell: a wall. */
    static final int CLOSED = 0;
    /** What the laser says of a side of a cell: open, a beam went through. */
    static final int OPEN = 1;
    /** Where along a side its beams are aimed, as fractions of its length: clear of the corners' posts. */
    private static final double[] AIMS = {0.3, 0.5, 0.7};
    /** The shallowest a beam may meet a side's line and still judge it, as the sine of the angle. */
    private static final double SHALLOWEST = 0.3;
    /** The farthest side the laser judges, mm. */
    private static final double FARTHEST = 5000;

    /**
     * Reads one side of a cell with the laser, from wherever the robot is: three beams aimed at marks
     * along the side, clear of its ends. A beam that goes on past the side's line (and the
     * thickness of a wall on it) proves the side open; the side is closed when at least two of the
     * marks are in view and every beam aimed at one ends on a wall's face on the line. Anything else
     * (the side out of view, met too shallow, too far, or something nearer in the way, such as a
     * teammate) leaves it unseen. A teammate standing in a doorway cannot close it: the marks lie
     * 450 mm apart, farther than a Pioneer is wide or long, so it covers at most one.
     *
     * @param robot    the robot, anywhere
     * @param scan     its laser's scan, 180° from its right, taken at its pose
     * @param cellSize mm
     * @param x        the cell's column
     * @param y        its row
     * @param side     0 east, 1 north, 2 west, 3 south
     * @return {@link #OPEN}, {@link #CLOSED} or {@link #UNSEEN}
     */
    static int side(ArRobot robot, int[] scan, double cellSize, int x, int y, int side) {
        if (scan.length < 3) {
            return UNSEEN;
        }
        double increment = 180.0 / (scan.length - 1);
        double th = robot.getTh();
        double lx = robot.getX() + robot.getParameters().laserX() * Math.cos(Math.toRadians(th));
        double ly = robot.getY() + robot.getParameters().laserX() * Math.sin(Math.toRadians(th));
        boolean vertical = side % 2 == 0;
        double line = vertical ? (x + (side == 0 ? 1 : 0)) * cellSize : (y + (side == 1 ? 1 : 0)) * cellSize;
        double from = (vertical ? y : x) * cellSize;
        int walls = 0;
        int seen = 0;
        for (double aim : AIMS) {
            double ax = vertical ? line : from + aim * cellSize;
            double ay = vertical ? from + aim * cellSize : line;
            double bearing = ArMath.fixAngle(Math.toDegrees(Math.atan2(ay - ly, ax - lx)) - th);
            if (Math.abs(bearing) > 90) {
                continue;
            }
            int i = (int) Math.round((bearing + 90) / increment);
            double beam = Math.toRadians(th + i * increment - 90);
            double across = vertical ? Math.cos(beam) : Math.sin(beam);
            double along = vertical ? Math.sin(beam) : Math.cos(beam);
            double t = ((vertical ? line - lx : line - ly)) / across;
            double where = ((vertical ? ly : lx) + t * along - from) / cellSize;
            if (Math.abs(across) < SHALLOWEST || t < 100 || t > FARTHEST || where < 0.15 || where > 0.85) {
                continue;
            }
            // a wall on the line is 100 mm thick: centred on it inside the maze, just inside it on the boundary
            double thick = 2 * WALL_HALF / Math.abs(across);
            if (scan[i] > t + thick / 2 + 100) {
                return OPEN;
            }
            seen++;
            if (scan[i] >= t - thick - 40 && scan[i] <= t - thick / 2 + 40) {
                walls++;
            }
        }
        return seen >= 2 && walls == seen ? CLOSED : UNSEEN;
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
