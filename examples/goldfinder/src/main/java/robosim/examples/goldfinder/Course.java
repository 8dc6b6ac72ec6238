package robosim.examples.goldfinder;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * Where a Gold robot is in the maze and where it is going: the cell it stands in, the side it
 * came in by, the cells ahead it has committed to drive through (it holds them: no teammate may
 * enter them), the frontier it has claimed or follows, and the cell it waits to enter while a
 * teammate holds it. The search changes it; the track, the team messages and the drawings read it.
 *
 * <p>The robot counts its cell itself, from its odometry: it starts in the cell under its starting
 * pose, and the cell it is in is the one under its pose.
 */
final class Course {
    private int x;
    private int y;
    /** The side of its cell the robot came in by, or -1 while it stands (it turns in place before it leaves). */
    private int entry = -1;
    /** The cells ahead it has committed to, in the order it drives through them. */
    private final List<Long> ahead = new ArrayList<>();
    private TeamPlan.Plan plan = TeamPlan.Plan.NONE;
    /** The key of the cell it waits to enter, or -1. */
    private long want = -1;
    /** How many steps it has waited for that cell. */
    private int waited;

    /**
     * @param x the starting cell's column
     * @param y its row
     */
    Course(int x, int y) {
        this.x = x;
        this.y = y;
    }

    /** @return the column of the cell the robot stands in */
    int x() {
        return x;
    }

    /** @return the row of the cell the robot stands in */
    int y() {
        return y;
    }

    /** @return the key of the cell the robot stands in */
    long here() {
        return MazeKnowledge.key(x, y);
    }

    /** @return the side of its cell it came in by, or -1 while it stands */
    int entry() {
        return entry;
    }

    /** @return the cells ahead it has committed to, nearest first (read only) */
    List<Long> ahead() {
        return Collections.unmodifiableList(ahead);
    }

    /** @return the last cell it has committed to: where it stops unless it commits more */
    long last() {
        return ahead.isEmpty() ? here() : ahead.get(ahead.size() - 1);
    }

    /** @return the side by which it comes into its last committed cell, or -1 if that is the cell it stands in */
    int lastEntry() {
        if (ahead.isEmpty()) {
            return entry;
        }
        long before = ahead.size() == 1 ? here() : ahead.get(ahead.size() - 2);
        return Track.sideTowards(last(), before);
    }

    /** Commits to a cell next to the last committed one: the robot will drive into it. */
    void commit(long cell) {
        Track.sideTowards(last(), cell);
        ahead.add(cell);
    }

    /** Gives up the committed cells from the {@code k}-th ahead (0: the nearest) on. */
    void cutFrom(int k) {
        ahead.subList(k, ahead.size()).clear();
    }

    /**
     * The robot is now in cell (cx, cy), by its pose. Coming into the next committed cell moves the
     * course on; coming into any other cell (pushed, or backing off) drops the committed cells.
     *
     * @return whether its cell changed
     */
    boolean moveTo(int cx, int cy) {
        if (cx == x && cy == y) {
            return false;
        }
        long cell = MazeKnowledge.key(cx, cy);
        boolean next = !ahead.isEmpty() && ahead.get(0) == cell;
        entry = next ? Track.sideTowards(cell, here()) : -1;
        if (next) {
            ahead.remove(0);
        } else {
            ahead.clear();
        }
        x = cx;
        y = cy;
        return true;
    }

    /** The robot stands (it has stopped): it turns in place before it leaves, and has committed to nothing. */
    void stand() {
        entry = -1;
        ahead.clear();
    }

    /** @return the frontier claimed or followed */
    TeamPlan.Plan plan() {
        return plan;
    }

    /** @param plan the frontier now claimed or followed */
    void plan(TeamPlan.Plan plan) {
        this.plan = plan;
    }

    /** @return the key of the cell it waits to enter, or -1 */
    long want() {
        return want;
    }

    /** @return how many steps it has waited for that cell */
    int waited() {
        return waited;
    }

    /** Begins to wait for a cell a teammate holds: the count of steps starts again. */
    void startWaiting(long cell) {
        want = cell;
        waited = 0;
    }

    /** Counts one more step of waiting. */
    void waitOneStep() {
        waited++;
    }

    /** Starts the count of steps again, still waiting for the same cell. */
    void restartPatience() {
        waited = 0;
    }

    /** Waits for no cell any more. */
    void stopWaiting() {
        want = -1;
        waited = 0;
    }
}
