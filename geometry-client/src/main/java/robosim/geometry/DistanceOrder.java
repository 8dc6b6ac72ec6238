package robosim.geometry;

import java.util.Arrays;

/**
 * The order of a gathering's edges by their distance from its centre: the indexes of the keys in
 * ascending order ({@link Double#compare}), equal keys in the order they came, as a stable sort
 * gives, without boxing. One instance keeps its arrays from one sort to the next, so a
 * {@link Surroundings} gathered again each step sorts without allocating.
 */
final class DistanceOrder {
    /** A bucket holding more keys than this sends the keys to the merge sort. */
    private static final int MAX_BUCKET = 32;
    /** Runs shorter than this are sorted by insertion. */
    private static final int INSERTION_RUN = 16;

    private int[] start = new int[1];
    private int[] bucket = new int[0];
    private int[] order = new int[0];

    /** @return the order of all of {@code keys}, in an array of its own */
    static int[] of(double[] keys) {
        return Arrays.copyOf(new DistanceOrder().sort(keys, keys.length), keys.length);
    }

    /**
     * The keys (the edges' distances) are spread evenly enough for a bucket sort: a counting sort
     * into as many buckets as keys, each bucket a slice of the range up to the largest key, then
     * insertion by the exact key and index, which has only the few keys sharing a bucket to put in
     * order.
     *
     * @param keys the keys; only the first {@code n} count
     * @param n    how many
     * @return the indexes of the first {@code n} keys in order, in the array's first {@code n}
     *         places; the array is this instance's own until its next sort
     */
    int[] sort(double[] keys, int n) {
        double max = 0;
        for (int i = 0; i < n; i++) {
            if (keys[i] > max) {
                max = keys[i];
            }
        }
        if (n < 2 || !(max > 0 && max < Double.POSITIVE_INFINITY)) {
            return mergeOrder(keys, n);
        }
        if (order.length < n) {
            start = new int[n + 1];
            bucket = new int[n];
            order = new int[n];
        } else {
            Arrays.fill(start, 0, n + 1, 0);
        }
        double scale = (n - 1) / max;
        for (int i = 0; i < n; i++) {
            double b = keys[i] * scale;
            int k = b >= 0 ? (int) Math.min(n - 1, b) : 0;
            bucket[i] = k;
            if (++start[k + 1] > MAX_BUCKET) {
                return mergeOrder(keys, n);
            }
        }
        for (int k = 0; k < n; k++) {
            start[k + 1] += start[k];
        }
        for (int i = 0; i < n; i++) {
            order[start[bucket[i]]++] = i;
        }
        for (int p = 1; p < n; p++) {
            int v = order[p];
            int j = p - 1;
            while (j >= 0 && after(keys, order[j], v)) {
                order[j + 1] = order[j];
                j--;
            }
            order[j + 1] = v;
        }
        return order;
    }

    /** @return whether index {@code a} comes after index {@code b}: a larger key, or an equal key and a larger index */
    private static boolean after(double[] keys, int a, int b) {
        int c = Double.compare(keys[a], keys[b]);
        return c > 0 || c == 0 && a > b;
    }

    /** The same order by a merge sort, for any keys. */
    static int[] mergeOrder(double[] keys) {
        return mergeOrder(keys, keys.length);
    }

    private static int[] mergeOrder(double[] keys, int n) {
        int[] a = new int[n];
        for (int i = 0; i < n; i++) {
            a[i] = i;
        }
        for (int lo = 0; lo < n; lo += INSERTION_RUN) {
            int hi = Math.min(n, lo + INSERTION_RUN);
            for (int i = lo + 1; i < hi; i++) {
                int v = a[i];
                int j = i - 1;
                while (j >= lo && Double.compare(keys[a[j]], keys[v]) > 0) {
                    a[j + 1] = a[j];
                    j--;
                }
                a[j + 1] = v;
            }
        }
        int[] b = new int[n];
        for (int width = INSERTION_RUN; width < n; width *= 2) {
            for (int lo = 0; lo < n; lo += 2 * width) {
                int mid = Math.min(n, lo + width);
                int hi = Math.min(n, lo + 2 * width);
                int i = lo;
                int j = mid;
                int k = lo;
                while (i < mid && j < hi) {
                    // the left run wins ties: equal keys keep their order
                    b[k++] = Double.compare(keys[a[j]], keys[a[i]]) < 0 ? a[j++] : a[i++];
                }
                while (i < mid) {
                    b[k++] = a[i++];
                }
                while (j < hi) {
                    b[k++] = a[j++];
                }
            }
            int[] t = a;
            a = b;
            b = t;
        }
        return a;
    }
}
