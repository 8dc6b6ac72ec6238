package robosim.examples.goldfinder;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import robosim.aria.ArRobot;

/**
 * The search, a step at a time. The robot senses as it drives, and drives without stopping from
 * cell to cell: it commits to the next cell of its way (and so holds it against its teammates)
 * only when it must, to drive on without braking, so that what it has just sensed and heard still
 * decides the way.
 *
 * <ol>
 *   <li>{@link Phase#DRIVE DRIVE}: each step, note the cell it has come into, read the cells around
 *       it, give up committed cells a teammate has taken first (while it can still stop before
 *       them), commit to the next cell when it must ({@link Wayfinder} chooses it), and drive its
 *       {@link Track} ({@link Driving}). Where it cannot go on (back the way it came, a cell a
 *       teammate holds, nothing left to do) it stops at a cell's centre, and standing there decides
 *       as a standing robot does: wait, step aside for a teammate that waits for its cell, or turn
 *       and go. Held back a while by a teammate on its track (its laser saw it; the messages had
 *       not told), it gives up the cells it had committed to, and the higher number of the two steps
 *       off the other's way;</li>
 *   <li>{@link Phase#BACK BACK}: something stopped it (a collision): back off a little, then decide
 *       standing;</li>
 *   <li>{@link Phase#DONE DONE}: the gold is found; stand still.</li>
 * </ol>
 *
 * Whenever it gives up, it waits a few steps (some of them drawn from its seed, so that two robots
 * in each other's way do not try again in step) before it decides again.
 */
final class SearchPhases {
    /** The phases of the search. */
    enum Phase { DRIVE, BACK, DONE }

    /** Steps a robot with nothing to claim or follow waits before it looks again. */
    private static final int IDLE_STEPS = 5;
    /** Steps a robot stands held back by something in its way before it decides again. */
    private static final int BLOCKED_STEPS = 15;
    /** How far past the side it came in by a robot may still take its cell's bend as an arc, mm. */
    private static final double LATE_ARC = 100;
    /** How far off the line to a side a standing robot may be and still leave by it straight, mm. */
    private static final double OFF_AXIS = 150;

    private final ArRobot robot;
    private final double cellSize;
    private final Survey survey;
    private final Wayfinder way;
    private final Driving driving;
    private final MazeKnowledge map;
    private final Course course;
    private final SplittableRandom random;
    private final int rank;
    private Phase phase = Phase.DRIVE;
    /** Steps to wait before deciding again. */
    private int pause;
    /** Steps the robot has stood held back by something in its way. */
    private int blockedFor;
    private boolean started;

    /**
     * @param robot    the robot
     * @param cellSize the maze's cell size, mm
     * @param survey   what it senses of the cells
     * @param way      its rules for choosing the way
     * @param driving  its motions
     * @param map      what it knows
     * @param course   where it is and goes
     * @param random   its seeded tie-breaks
     */
    SearchPhases(ArRobot robot, double cellSize, Survey survey, Wayfinder way, Driving driving, MazeKnowledge map,
                 Course course, SplittableRandom random) {
        this.robot = robot;
        this.cellSize = cellSize;
        this.survey = survey;
        this.way = way;
        this.driving = driving;
        this.map = map;
        this.course = course;
        this.random = random;
        this.rank = Gold.rankOf(robot.getName());
    }

    /** Does the current phase's part of one step. */
    void step() {
        if (!started) {
            started = true;
            survey.senseHereStanding();
            way.newOrder();
        }
        switch (phase) {
            case DRIVE -> drive();
            case BACK -> back();
            default -> { }
        }
    }

    /** @return whether the search is over */
    boolean done() {
        return phase == Phase.DONE;
    }

    /** Ends the search: the gold is found. */
    void end() {
        phase = Phase.DONE;
        driving.halt();
    }

    private void drive() {
        locate();
        survey.sense();
        if (driving.isStalled()) {
            // something unexpected is in the way: back off, then think again
            driving.backOff();
            course.stand();
            phase = Phase.BACK;
            return;
        }
        giveUpContested();
        if (pause > 0) {
            pause--;
        } else {
            extend();
        }
        if (driving.follow(track())) {
            course.stand();
            if (nearCentre()) {
                survey.senseHereStanding(); // the sides the laser cannot see from here: beside it, behind it
            }
        }
        blockedFor = driving.blocked() && Math.abs(robot.getVel()) < 20 ? blockedFor + 1 : 0;
        if (blockedFor > BLOCKED_STEPS) {
            // a teammate stands in the way: stop holding the cells beyond it; the higher number of the
            // two steps off the other's way, the other thinks again
            blockedFor = 0;
            List<Long> meant = new ArrayList<>(course.ahead());
            driving.halt();
            course.stand();
            String blocker = way.blocker(meant);
            if (blocker != null && Gold.rankOf(blocker) < rank) {
                int aside = way.sideAside(blocker);
                if (aside >= 0 && leaveBy(aside)) {
                    return;
                }
            }
            pause = 5 + random.nextInt(10);
        }
    }

    /** Notes the cell the robot has come into, by its pose. */
    private void locate() {
        if (course.moveTo((int) Math.floor(robot.getX() / cellSize), (int) Math.floor(robot.getY() / cellSize))) {
            if (course.entry() >= 0) {
                survey.cameThrough(course.entry());
            }
            way.newOrder();
        }
    }

    private Track track() {
        return new Track(course, cellSize, robot.getX(), robot.getY());
    }

    /** Commits to more cells while the way to the track's end is shorter than the robot needs to drive on. */
    private void extend() {
        double v = Math.abs(robot.getVel());
        double dt = robot.getStepMs() / 1000.0;
        double horizon = v * v / (2 * Driving.BRAKING) + cellSize / 2 + 300 + 2 * v * dt;
        for (int k = 0; k < 3 && track().toStop() < horizon; k++) {
            if (!commitNext()) {
                return;
            }
        }
    }

    /** @return whether it committed to one more cell */
    private boolean commitNext() {
        int side = way.chooseSide();
        if (course.ahead().isEmpty() && course.entry() < 0) {
            return decideStanding(side);
        }
        if (side < 0 || side == course.lastEntry()) {
            return false; // nothing to do, or back the way it came: stop first
        }
        if (course.ahead().isEmpty() && side != (course.entry() + 2) % 4 && pastEntry() > LATE_ARC) {
            return false; // too late to take the bend as an arc: stop at the centre and turn there
        }
        long next = neighbour(course.last(), side);
        if (map.heldAgainst(next, course.last())) {
            return false; // a teammate holds it: stop, and wait standing
        }
        course.commit(next);
        course.stopWaiting();
        return true;
    }

    /** The standing robot's decision: step aside for a teammate, wait for a held cell, idle, or go. */
    private boolean decideStanding(int side) {
        String waiting = way.waitedForBy();
        if (waiting != null && way.givesWayTo(waiting, side)) {
            int aside = way.sideAside(waiting);
            if (aside >= 0) {
                return leaveBy(aside);
            }
        }
        if (side < 0) {
            course.stopWaiting();
            pause = IDLE_STEPS;
            return false;
        }
        if (way.heldByTeammate(side)) {
            int otherWay = way.waitFor(side);
            return otherWay >= 0 && leaveBy(otherWay);
        }
        return leaveBy(side);
    }

    /** Commits a standing robot to the cell across {@code side}, if it stands on the line to it; else it goes to its centre first. */
    private boolean leaveBy(int side) {
        double cx = (course.x() + 0.5) * cellSize;
        double cy = (course.y() + 0.5) * cellSize;
        double off = Directions.dx(side) != 0 ? robot.getY() - cy : robot.getX() - cx;
        if (Math.abs(off) > OFF_AXIS) {
            return false;
        }
        course.commit(neighbour(course.here(), side));
        course.stopWaiting();
        return true;
    }

    /** @return whether the robot stands within a fifth of a cell of its cell's centre */
    private boolean nearCentre() {
        return Math.hypot(robot.getX() - (course.x() + 0.5) * cellSize, robot.getY() - (course.y() + 0.5) * cellSize)
                < cellSize / 5;
    }

    /** How far the robot is past the side of its cell it came in by, mm. */
    private double pastEntry() {
        int e = course.entry();
        double mx = (course.x() + 0.5 + 0.5 * Directions.dx(e)) * cellSize;
        double my = (course.y() + 0.5 + 0.5 * Directions.dy(e)) * cellSize;
        return -((robot.getX() - mx) * Directions.dx(e) + (robot.getY() - my) * Directions.dy(e));
    }

    /**
     * Gives up the committed cells from the first one a teammate has taken first, if the robot can
     * still stop short of it; else it drives on, and its laser keeps it off the teammate.
     */
    private void giveUpContested() {
        int k = way.firstContested();
        if (k < 0) {
            return;
        }
        Track t = track();
        double v = robot.getVel();
        if ((k > 0 || !t.bendsFirst()) && t.toCell(k) + cellSize / 2 >= v * v / (2 * 280) + 30) {
            course.cutFrom(k);
        }
    }

    private void back() {
        if (driving.backingOver()) {
            driving.halt();
            locate();
            course.stand();
            phase = Phase.DRIVE;
            pause = 5 + random.nextInt(10);
        }
    }

    private static long neighbour(long cell, int side) {
        return MazeKnowledge.key(MazeKnowledge.keyX(cell) + Directions.dx(side),
                MazeKnowledge.keyY(cell) + Directions.dy(side));
    }
}
