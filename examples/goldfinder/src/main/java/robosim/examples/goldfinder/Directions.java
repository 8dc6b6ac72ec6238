package robosim.examples.goldfinder;

/**
 * The four sides of a cell, numbered the same way everywhere in GoldFinder: 0 east, 1 north, 2 west,
 * 3 south (so side d faces d × 90°), and the step, in cells, that leads across each side. Cell
 * (0, 0) is the maze's lower left corner; columns grow east, rows grow north.
 */
final class Directions {
    /** East, north, west, south: the column and row steps across each side. */
    private static final int[][] STEPS = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};

    private Directions() {
    }

    /** @return how the column changes across side {@code d} */
    static int dx(int d) {
        return STEPS[d][0];
    }

    /** @return how the row changes across side {@code d} */
    static int dy(int d) {
        return STEPS[d][1];
    }
}
