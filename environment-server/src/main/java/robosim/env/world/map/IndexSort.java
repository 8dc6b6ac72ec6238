package robosim.env.world.map;

/**
 * Sorts item indices by one number of the items, then another, on primitive arrays: a scanned
 * map's 10^5 points sort in a few milliseconds even before the JIT has compiled anything, which a
 * boxed comparator sort does not.
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
        int[] buffer = new int[idx.length];
        int[] from = idx;
        int[] to = buffer;
        for (int width = 1; width < idx.length; width *= 2) {
            for (int lo = 0; lo < idx.length; lo += 2 * width) {
                int mid = Math.min(lo + width, idx.length);
                int hi = Math.min(lo + 2 * width, idx.length);
                merge(from, to, lo, mid, hi, table, first, second);
            }
            int[] t = from;
            from = to;
            to = t;
        }
        if (from != idx) {
            System.arraycopy(from, 0, idx, 0, idx.length);
        }
    }

    private static void merge(int[] from, int[] to, int lo, int mid, int hi, Table table, int first, int second) {
        int a = lo;
        int b = mid;
        for (int k = lo; k < hi; k++) {
            if (a < mid && (b >= hi || !before(from[b], from[a], table, first, second))) {
                to[k] = from[a++];
            } else {
                to[k] = from[b++];
            }
        }
    }

    /** @return whether item i sorts strictly before item j */
    private static boolean before(int i, int j, Table table, int first, int second) {
        double a = table.at(i, first);
        double b = table.at(j, first);
        if (a != b) {
            return a < b;
        }
        return table.at(i, second) < table.at(j, second);
    }
}
