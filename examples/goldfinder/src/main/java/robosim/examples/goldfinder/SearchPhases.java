package robosim.examples.goldfinder;

import static robosim.examples.goldfinder.MazeKnowledge.NONE;

import java.util.SplittableRandom;

/**
 * The search as a state machine: each step a Gold robot is in one phase and does that phase's part.
 *
 * <ol>
 *   <li>{@link Phase#DECIDE DECIDE}, standing at a cell's centre: sense the cell and the cells ahead,
 *       choose a run of cells to drive ({@link Wayfinder}), or wait a little;</li>
 *   <li>{@link Phase#ANNOUNCE ANNOUNCE}: the run was told to the team one step ago; if a teammate
 *       has since taken one of its cells, decide again, else start turning;</li>
 *   <li>{@link Phase#TURN TURN}: once facing the way, read the cells ahead (which may change the
 *       way), cut the run to what the laser sees clear, and drive;</li>
 *   <li>{@link Phase#MOVE MOVE}: drive to the run's last cell, then decide there; when something
 *       stops the robot on the way, back off;</li>
 *   <li>{@link Phase#BACK BACK}: back to the last cell's centre it passed, then decide;</li>
 *   <li>{@link Phase#DONE DONE}: the gold is found; stand still.</li>
 * </ol>
 *
 * Whenever it gives up on a move it tells its team that it stands still, and waits a few steps
 * (some of them drawn from its seed, so that two robots in each other's way do not try again in
 * step) before it decides again.
 */
final class SearchPhases {
    /** The phases of the search, in the order a move goes through them. */
    enum Phase { DECIDE, ANNOUNCE, TURN, MOVE, BACK, DONE }

    /** Steps a robot with nothing to claim or follow waits before it looks again. */
    private static final int IDLE_STEPS = 5;

    private final Survey survey;
    private final Wayfinder way;
    private final Driving driving;
    private final TeamTalk team;
    private final Course course;
    private final SplittableRandom random;
    private Phase phase = Phase.DECIDE;
    /** Steps to wait before deciding again. */
    private int pause;
    /** Whether the robot read the cells ahead since it last turned. */
    private boolean lookedAhead;

    /**
     * @param survey  what it senses of the cells
     * @param way     its rules for choosing the way
     * @param driving its motions
     * @param team    its messages
     * @param course  where it is and goes
     * @param random  its seeded tie-breaks
     */
    SearchPhases(Survey survey, Wayfinder way, Driving driving, TeamTalk team, Course course,
                 SplittableRandom random) {
        this.survey = survey;
        this.way = way;
        this.driving = driving;
        this.team = team;
        this.course = course;
        this.random = random;
    }

    /** Does the current phase's part of one step. */
    void step() {
        switch (phase) {
            case DECIDE -> decide();
            case ANNOUNCE -> announce();
            case TURN -> turn();
            case MOVE -> drive();
            case BACK -> back();
            default -> { }
        }
    }

    /** @return whether the robot is about to drive or is driving a run */
    boolean underWay() {
        return phase == Phase.ANNOUNCE || phase == Phase.TURN || phase == Phase.MOVE;
    }

    /** @return whether the search is over */
    boolean done() {
        return phase == Phase.DONE;
    }

    /** Ends the search: the gold is found. */
    void end() {
        phase = Phase.DONE;
    }

    private void decide() {
        if (pause > 0) {
            pause--;
            return;
        }
        survey.senseHereIfNew();
        survey.lookAhead();
        int[] order = way.order();
        int side = way.chooseSide(order);
        String waiting = way.waitedForBy();
        if (waiting != null && way.givesWayTo(waiting, side)) {
            int aside = way.sideAside(waiting);
            if (aside >= 0) {
                go(aside, 1);
                return;
            }
        }
        if (side < 0) {
            idle();
            return;
        }
        if (way.heldByTeammate(side)) {
            int otherWay = way.waitFor(side);
            if (otherWay >= 0) {
                go(otherWay, 1);
            }
            return;
        }
        go(side, way.runLength(side, order));
    }

    /** Nothing to claim or follow: say so, and look again in a few steps. */
    private void idle() {
        course.stopWaiting();
        team.tell(NONE, NONE, false);
        pause = IDLE_STEPS;
    }

    /** Sets out on a run of {@code cells} cells across {@code side}, and tells the team where to. */
    private void go(int side, int cells) {
        course.run(side, cells);
        course.stopWaiting();
        team.tell(course.aheadX(cells), course.aheadY(cells), false);
        lookedAhead = false;
        phase = Phase.ANNOUNCE;
    }

    private void announce() {
        if (way.runContested()) {
            decideAgainAfter(1);
            return;
        }
        driving.startTurn();
        phase = Phase.TURN;
    }

    private void turn() {
        if (driving.turnTakesTooLong()) {
            // something keeps the robot from turning (a teammate pressed against it): think again
            driving.stop();
            decideAgainAfter(5 + random.nextInt(10));
            return;
        }
        if (!driving.isTurned()) {
            return;
        }
        if (!lookedAhead) {
            lookedAhead = true;
            if (survey.lookAhead() > 0) {
                phase = Phase.DECIDE; // what it saw may change the way
                return;
            }
        }
        // the laser has the last word: a teammate the messages have not told of may stand ahead
        course.shortenTo(driving.clearCellsAhead());
        if (course.cells() == 0) {
            decideAgainAfter(5 + random.nextInt(10));
            return;
        }
        driving.startRun();
        phase = Phase.MOVE;
    }

    private void drive() {
        if (driving.isStalled()) {
            // something unexpected is in the way: back to the centre of the last cell it drove through
            driving.backToLastCentre();
            phase = Phase.BACK;
            team.tell(NONE, NONE, false);
            return;
        }
        if (driving.arrived()) {
            course.advance(course.cells());
            phase = Phase.DECIDE;
            survey.senseHereIfNew();
            team.tell(NONE, NONE, false);
        }
    }

    private void back() {
        if (driving.backingOver()) {
            // blocked again (a teammate came up behind): stop where it is; the next move makes good the offset
            driving.stop();
            decideAgainAfter(5 + random.nextInt(10));
        }
    }

    /** Gives up the move: decide again after {@code steps} steps, and tell the team it stands still. */
    private void decideAgainAfter(int steps) {
        phase = Phase.DECIDE;
        pause = steps;
        team.tell(NONE, NONE, false);
    }
}
