package robosim.examples.goldfinder;

/**
 * What a Gold robot tells its team, broadcast through the Environment: where it is and the cells
 * ahead it has committed to drive through, the frontier it has claimed (or follows), the cell it waits to enter, walls it sensed,
 * and whether it has found the gold. Each robot repeats its report every few steps and with it
 * some of the cells it sensed, old ones in turn, so that a lost message costs a little time and
 * nothing else. Cells are given by column and row; {@link MazeKnowledge#NONE} stands for no cell.
 *
 * @param robot   the sender
 * @param x       its cell's column
 * @param y       its cell's row
 * @param route   the cells ahead it has committed to drive through, nearest first, two numbers each:
 *                column, row (none when it stands)
 * @param targetX the column of the frontier it claimed or follows, or NONE
 * @param targetY the row of that frontier
 * @param claim   whether it claims the target (false: it only follows a teammate's claim there)
 * @param wantX   the column of the cell it waits to enter (a teammate holds it), or NONE
 * @param wantY   the row of that cell
 * @param cells   cells it sensed, three numbers each: column, row, open sides (bit d set when side d,
 *                0 east, 1 north, 2 west, 3 south, is open)
 * @param gold    whether the sender has found the gold
 */
public record MazeMessage(String robot, int x, int y, int[] route, int targetX, int targetY, boolean claim,
                          int wantX, int wantY, int[] cells, boolean gold) {
    /** The most cells ahead a report may say its robot has committed to. */
    public static final int MOST_AHEAD = 16;

    /** Checks the route's and the cells' layout, so a malformed report is refused as a whole. */
    public MazeMessage {
        if (robot == null || robot.isBlank()) {
            throw new IllegalArgumentException("a maze message must name its robot");
        }
        route = route == null ? new int[0] : route.clone();
        if (route.length % 2 != 0 || route.length > 2 * MOST_AHEAD) {
            throw new IllegalArgumentException(route.length + " numbers were supplied for route: two per cell, at most "
                    + MOST_AHEAD + " cells");
        }
        cells = cells == null ? new int[0] : cells.clone();
        if (cells.length % 3 != 0) {
            throw new IllegalArgumentException(cells.length + " numbers were supplied for cells: three per cell");
        }
        for (int i = 2; i < cells.length; i += 3) {
            if (cells[i] < 0 || cells[i] > 15) {
                throw new IllegalArgumentException(cells[i] + " was supplied for a cell's open sides: 0 to 15");
            }
        }
    }
}
