package robosim.examples.goldfinder;

/**
 * Where a Gold robot is in the maze and where it is going: the cell it stands in, the straight run
 * of cells it drives (a side of its cell and how many cells), the frontier it has claimed or
 * follows, and the cell it waits to enter while a teammate holds it. The search changes it; the
 * team messages and the drawings report it.
 *
 * <p>The robot counts its cell itself, from the cells it drove: it starts in the cell under its
 * starting pose and moves on by whole cells.
 */
final class Course {
    private int x;
    private int y;
    /** The side of the cell the run leaves by, or -1 before the first run. */
    private int dir = -1;
    /** How many cells the run crosses. */
    private int cells = 1;
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

    /** @return the side the run leaves by, or -1 before the first run */
    int dir() {
        return dir;
    }

    /** @return how many cells the run crosses */
    int cells() {
        return cells;
    }

    /** @return the column of the cell {@code k} cells along the run */
    int aheadX(int k) {
        return x + k * Directions.dx(dir);
    }

    /** @return the row of the cell {@code k} cells along the run */
    int aheadY(int k) {
        return y + k * Directions.dy(dir);
    }

    /**
     * Sets out on a new run.
     *
     * @param side  the side of this cell it leaves by
     * @param count how many cells it crosses
     */
    void run(int side, int count) {
        dir = side;
        cells = count;
    }

    /** Cuts the run short to at most {@code clear} cells (0: it cannot go at all). */
    void shortenTo(int clear) {
        cells = Math.min(cells, clear);
    }

    /** Moves the robot's cell {@code k} cells along the run: it has driven them. */
    void advance(int k) {
        x += k * Directions.dx(dir);
        y += k * Directions.dy(dir);
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
