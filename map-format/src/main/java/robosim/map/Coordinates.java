package robosim.map;

import java.util.Arrays;

/**
 * Items of a map (points of x, y; lines of x1, y1, x2, y2) as they are read, in file order, on
 * primitive arrays: 8 bytes a number, in blocks of {@value #BLOCK} items, so that growing never
 * copies more than one block, and the file line of each item kept only where it does not follow
 * the item before's (a map's data lines follow each other, so usually a few numbers in all).
 * A map of 10^7 points costs 160 MB here, and nothing per point besides.
 */
public final class Coordinates {
    private static final int SHIFT = 14;
    /** Items per block. */
    static final int BLOCK = 1 << SHIFT;
    private static final int MASK = BLOCK - 1;

    private final int width;
    private double[][] blocks = new double[1][];
    private int count;
    /** Where the items' lines jump: from item starts[k] on, item i is on line lines[k] + i - starts[k]. */
    private int[] starts = new int[4];
    private int[] lines = new int[4];
    private int jumps;

    /** @param width the numbers per item: 2 for points, 4 for lines */
    public Coordinates(int width) {
        this.width = width;
        blocks[0] = new double[16 * width];
    }

    /**
     * Makes items of flat arrays.
     *
     * @param width  the numbers per item
     * @param values the items' numbers, {@code width} each
     * @param lines  each item's file line, increasing
     * @return them
     */
    public static Coordinates of(int width, double[] values, int[] lines) {
        Coordinates c = new Coordinates(width);
        for (int i = 0; i < lines.length; i++) {
            c.add(values, i * width, lines[i]);
        }
        return c;
    }

    /**
     * Adds an item.
     *
     * @param values where its numbers are
     * @param from   the index of its first number
     * @param line   its file line, after the previous item's
     */
    public void add(double[] values, int from, int line) {
        int block = count >>> SHIFT;
        int at = (count & MASK) * width;
        if (block == blocks.length) {
            blocks = Arrays.copyOf(blocks, 2 * block);
        }
        if (blocks[block] == null) {
            blocks[block] = new double[BLOCK * width];
        } else if (at == blocks[block].length) {
            // only the first block grows by doubling, so that a small map stays small
            blocks[block] = Arrays.copyOf(blocks[block], Math.min(2 * at, BLOCK * width));
        }
        System.arraycopy(values, from, blocks[block], at, width);
        if (count == 0 || line != line(count - 1) + 1) {
            jump(line);
        }
        count++;
    }

    private void jump(int line) {
        if (jumps == starts.length) {
            starts = Arrays.copyOf(starts, 2 * jumps);
            lines = Arrays.copyOf(lines, 2 * jumps);
        }
        starts[jumps] = count;
        lines[jumps++] = line;
    }

    /** @return the number of items */
    public int count() {
        return count;
    }

    /**
     * @param item   an item
     * @param number which of its numbers: 0 is x (x1), 1 is y (y1), ...
     * @return that number
     */
    public double get(int item, int number) {
        return blocks[item >>> SHIFT][(item & MASK) * width + number];
    }

    /**
     * @param item an item
     * @return the 1-based file line it was read from
     */
    public int line(int item) {
        int lo = 0;
        int hi = jumps - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (starts[mid] <= item) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lines[lo] + item - starts[lo];
    }

    /** @return all the numbers, {@code width} per item, in a new array */
    double[] values() {
        double[] out = new double[count * width];
        for (int i = 0; i < count; i++) {
            for (int k = 0; k < width; k++) {
                out[i * width + k] = get(i, k);
            }
        }
        return out;
    }

    /** @return every item's file line, in a new array */
    int[] lineNumbers() {
        int[] out = new int[count];
        for (int i = 0; i < count; i++) {
            out[i] = line(i);
        }
        return out;
    }
}
