package robosim.examples.goldfinder;

import robosim.aria.ArRobot;
import robosim.aria.ArSick;

/**
 * How a Gold robot moves from cell to cell, in ARIA's motion calls: it turns to face the side its
 * run leaves by, drives straight to the centre of the run's last cell, and, when something stops
 * it on the way, backs to the centre of the last cell it drove through. Every distance is measured
 * from where the robot is (by its odometry) along its way, so a start off a cell's centre is made
 * good. Which run to drive, and when, is {@link SearchPhases}'s business.
 */
final class Driving {
    /** The longest a robot tries to turn, steps (a quarter turn takes about 20). */
    private static final int TURN_STEPS = 80;
    /** The longest a robot tries to back off an obstacle, steps. */
    private static final int BACK_STEPS = 60;
    /** The room a robot leaves before an echo ahead, mm. */
    private static final double CLEARANCE = 100;

    private final ArRobot robot;
    private final ArSick laser;
    private final double cellSize;
    private final Course course;
    /** The step the robot began to turn, and to back off an obstacle. */
    private long turnSince;
    private long backSince;

    /**
     * @param robot    the robot
     * @param laser    its laser, switched on
     * @param cellSize the maze's cell size, mm
     * @param course   its cell and its run, which the motions follow and move on
     */
    Driving(ArRobot robot, ArSick laser, double cellSize, Course course) {
        this.robot = robot;
        this.laser = laser;
        this.cellSize = cellSize;
        this.course = course;
    }

    /** Turns the robot to face the side its run leaves by. */
    void startTurn() {
        robot.setHeading(course.dir() * 90);
        turnSince = robot.getStep();
    }

    /** @return whether the turn has taken longer than it ever should (a teammate pressed against it) */
    boolean turnTakesTooLong() {
        return robot.getStep() - turnSince > TURN_STEPS;
    }

    /** @return whether the robot faces its way and has stopped turning */
    boolean isTurned() {
        return robot.isHeadingDone(0.5) && Math.abs(robot.getRotVel()) < 1;
    }

    /**
     * How many cells of the run the robot can drive into, by its laser's beam straight ahead: the
     * echo must lie beyond the far cell's centre by the robot's front and a margin.
     *
     * @return 0 to the run's length
     */
    int clearCellsAhead() {
        int[] scan = laser.getRawScan();
        if (scan.length == 0) {
            return course.cells();
        }
        double reach = scan[scan.length / 2] + robot.getParameters().laserX();
        double front = robot.getParameters().robotLengthFront() + CLEARANCE;
        int cells = 0;
        while (cells < course.cells()
                && along(course.aheadX(cells + 1), course.aheadY(cells + 1)) + front <= reach) {
            cells++;
        }
        return cells;
    }

    /** Drives to the centre of the run's last cell. */
    void startRun() {
        robot.move(along(course.aheadX(course.cells()), course.aheadY(course.cells())));
    }

    /** @return whether the robot has driven as far as it was told and stands still */
    boolean arrived() {
        return robot.isMoveDone(1) && robot.isStopped();
    }

    /** @return whether a collision stopped the robot */
    boolean isStalled() {
        return robot.isStalled();
    }

    /**
     * Stops, and backs to the centre of the last cell of the run it drove through: the robot's
     * cell moves on to that cell.
     */
    void backToLastCentre() {
        robot.stop();
        int crossed = (int) Math.floor(along(course.x(), course.y()) / -cellSize);
        crossed = Math.max(0, Math.min(course.cells() - 1, crossed));
        course.advance(crossed);
        robot.move(along(course.x(), course.y()));
        backSince = robot.getStep();
    }

    /** @return whether backing off is over: arrived, blocked again, or taking too long */
    boolean backingOver() {
        boolean blocked = robot.isStalled() || robot.getStep() - backSince > BACK_STEPS;
        return (robot.isMoveDone(1) && robot.isStopped()) || blocked;
    }

    /** Stops where the robot is. */
    void stop() {
        robot.stop();
    }

    /**
     * The signed distance, along the robot's direction of travel, from where it is to a cell's
     * centre: negative when the centre lies behind.
     */
    private double along(int x, int y) {
        return ((x + 0.5) * cellSize - robot.getX()) * Directions.dx(course.dir())
                + ((y + 0.5) * cellSize - robot.getY()) * Directions.dy(course.dir());
    }
}
