package robosim.env.world.map;

/**
 * Sorts point indices by one coordinate, then the other, on primitive arrays: a scanned map's 10^5
 * points sort in a few milliseconds even before the JIT has compiled anything, which a boxed
 * comparator sort does not.
 */
final class IndexSort {
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
        int[] buffer = new int[idx.length];
        int[] from = idx;
        int[] to = buffer;
        for (int width = 1; width < idx.length; width *= 2) {
            for (int lo = 0; lo < idx.length; lo += 2 * width) {
                int mid = Math.min(lo + width, idx.length);
                int hi = Math.min(lo + 2 * width, idx.length);
                merge(from, to, lo, mid, hi, xy, major);
            }
            int[] t = from;
            from = to;
            to = t;
        }
        if (from != idx) {
            System.arraycopy(from, 0, idx, 0, idx.length);
        }
    }

    private static void merge(int[] from, int[] to, int lo, int mid, int hi, double[] xy, int major) {
        int a = lo;
        int b = mid;
        for (int k = lo; k < hi; k++) {
            if (a < mid && (b >= hi || !before(from[b], from[a], xy, major))) {
                to[k] = from[a++];
            } else {
                to[k] = from[b++];
            }
        }
    }

    /** @return whether point i sorts strictly before point j */
    private static boolean before(int i, int j, double[] xy, int major) {
        double a = xy[2 * i + major];
        double b = xy[2 * j + major];
        if (a != b) {
            return a < b;
        }
        return xy[2 * i + 1 - major] < xy[2 * j + 1 - major];
    }
}
