package robosim.env.world.map;

import robosim.geometry.KeyOrder;

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

    /** Sorts {@code idx} stably by one column, as {@link KeyOrder} sorts: by the column's values, -0 as 0. */
    private static void byColumn(int[] idx, Table table, int column, long[] keys, long[] keyBuffer, int[] idxBuffer) {
        for (int i = 0; i < idx.length; i++) {
            keys[i] = KeyOrder.key(table.at(idx[i], column));
        }
        KeyOrder.sort(keys, idx, 0, idx.length, keyBuffer, idxBuffer);
    }
}
