package robosim.examples.goldfinder;

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
