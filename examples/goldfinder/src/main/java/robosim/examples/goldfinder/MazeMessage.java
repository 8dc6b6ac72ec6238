package robosim.examples.goldfinder;

/**
 * What a Gold robot tells its team, broadcast through the Environment: where it is, what it found
 * out about its cell's walls, where it is going next, and whether it has found the gold.
 *
 * @param robot  the sender
 * @param x      its cell's column
 * @param y      its cell's row
 * @param sensed whether {@code open} holds sensed walls for that cell
 * @param open   bit d set when side d (0 east, 1 north, 2 west, 3 south) is open
 * @param nextX  the column of the cell it is heading for, or -1
 * @param nextY  the row of the cell it is heading for, or -1
 * @param gold   whether the sender has found the gold
 */
public record MazeMessage(String robot, int x, int y, boolean sensed, int open, int nextX, int nextY, boolean gold) {
}
