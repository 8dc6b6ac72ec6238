package robosim.env.world.map;

/**
 * Sorts item indices by one number of the items, then another, on primitive arrays: stably by
 * the second number, then stably by the first, each a radix sort of the numbers (as longs that
 * order as the doubles do) together with the indices, a byte at a time, skipping the bytes all
 * keys share (a map's whole millimetres leave most of a double's bytes alike). No comparison
 * waits on memory, so 10^6 scattered points sort in a fraction of a second; and the order is the
 * one a stable sort comparing the numbers gives.
 */
final class IndexSort {
    /** Numbers of items, by item and column. */
    @FunctionalInterface
    interface Table {
        /**
         * @param item   an item
         * @param column which of its numbers
         * @return that number
         */
        double at(int item, int column);
    }

    private IndexSort() {
    }

    /**
     * Sorts {@code idx} in place, stably, by {@code xy[2i + major]}, then {@code xy[2i + 1 - major]}.
     *
     * @param idx   point indices
     * @param xy    x0, y0, x1, y1, ...
     * @param major 0 to sort by x first, 1 by y first
     */
    static void sort(int[] idx, double[] xy, int major) {
        sort(idx, (i, k) -> xy[2 * i + k], major, 1 - major);
    }

    /**
     * Sorts {@code idx} in place, stably, by column {@code first} of the table, then column {@code second}.
     *
     * @param idx    item indices
     * @param table  the items' numbers
     * @param first  the column sorted by
     * @param second the column that breaks ties
     */
    static void sort(int[] idx, Table table, int first, int second) {
        long[] keys = new long[idx.length];
        long[] keyBuffer = new long[idx.length];
        int[] idxBuffer = new int[idx.length];
        byColumn(idx, table, second, keys, keyBuffer, idxBuffer);
        byColumn(idx, table, first, keys, keyBuffer, idxBuffer);
    }

    /** Below this many items a column is sorted by insertion: a hull's few corners need no more. */
    private static final int SMALL = 32;

    /** Sorts {@code idx} stably by one column: by insertion when small, else by radix, a byte at a time. */
    private static void byColumn(int[] idx, Table table, int column, long[] keys, long[] keyBuffer, int[] idxBuffer) {
        int n = idx.length;
        for (int i = 0; i < n; i++) {
            keys[i] = key(table.at(idx[i], column)) ^ Long.MIN_VALUE; // unsigned order, for the bytes
        }
        if (n < SMALL) {
            insertion(idx, keys, n);
            return;
        }
        int[][] counts = new int[8][256];
        for (int i = 0; i < n; i++) {
            for (int b = 0; b < 8; b++) {
                counts[b][(int) (keys[i] >>> (8 * b)) & 0xff]++;
            }
        }
        long[] fromKeys = keys;
        int[] from = idx;
        long[] toKeys = keyBuffer;
        int[] to = idxBuffer;
        for (int b = 0; b < 8; b++) {
            int[] count = counts[b];
            if (count[(int) (fromKeys[0] >>> (8 * b)) & 0xff] == n) {
                continue; // every key has this byte: the pass would change nothing
            }
            for (int d = 0, sum = 0; d < 256; d++) {
                int c = count[d];
                count[d] = sum;
                sum += c;
            }
            for (int i = 0; i < n; i++) {
                int at = count[(int) (fromKeys[i] >>> (8 * b)) & 0xff]++;
                toKeys[at] = fromKeys[i];
                to[at] = from[i];
            }
            long[] tk = fromKeys;
            fromKeys = toKeys;
            toKeys = tk;
            int[] t = from;
            from = to;
            to = t;
        }
        if (from != idx) {
            System.arraycopy(from, 0, idx, 0, n);
        }
    }

    private static void insertion(int[] idx, long[] keys, int n) {
        for (int i = 1; i < n; i++) {
            long k = keys[i];
            int v = idx[i];
            int j = i - 1;
            while (j >= 0 && Long.compareUnsigned(keys[j], k) > 0) {
                keys[j + 1] = keys[j];
                idx[j + 1] = idx[j];
                j--;
            }
            keys[j + 1] = k;
            idx[j + 1] = v;
        }
    }

    /**
     * @param v a number, not NaN
     * @return a long that orders as {@code v} does among numbers compared with {@code <}: -0 is 0
     */
    static long key(double v) {
        long bits = Double.doubleToRawLongBits(v + 0.0);
        return bits >= 0 ? bits : bits ^ Long.MAX_VALUE;
    }
}
