package robosim.geometry;

import java.util.Arrays;

/**
 * A stable sort of items by keys on primitive arrays: a radix sort of the keys' bytes, least
 * significant first, skipping the bytes all keys of the range share. Equal keys keep their items'
 * order, so the result is the one order any stable sort gives.
 */
public final class KeyOrder {
    /** Ranges this short are sorted by insertion. */
    private static final int INSERTION_RUN = 24;

    private KeyOrder() {
    }

    /**
     * A key whose unsigned order is the numeric order of finite doubles, with -0.0 and 0.0 equal:
     * the order of JTS's {@code compareDoubles}, which its STRtree sorts by.
     *
     * @param d a double, not NaN
     * @return its key
     */
    public static long key(double d) {
        long bits = Double.doubleToRawLongBits(d + 0.0); // -0.0 + 0.0 is 0.0
        return bits < 0 ? ~bits : bits ^ Long.MIN_VALUE;
    }

    /**
     * Sorts {@code items[from, to)} by {@code keys[from, to)} (unsigned), the keys moving with their
     * items; equal keys keep their order.
     *
     * @param keys        the keys
     * @param items       the items
     * @param from        first index of the range
     * @param to          one past its last
     * @param keyScratch  room for the keys of the range, at the same indexes
     * @param itemScratch room for the items of the range, at the same indexes
     */
    public static void sort(long[] keys, int[] items, int from, int to, long[] keyScratch, int[] itemScratch) {
        if (to - from <= INSERTION_RUN) {
            insertion(keys, items, from, to);
            return;
        }
        long[] srcK = keys;
        int[] srcI = items;
        long[] dstK = keyScratch;
        int[] dstI = itemScratch;
        int[] start = new int[257];
        for (int shift = 0; shift < Long.SIZE; shift += Byte.SIZE) {
            if (!count(srcK, from, to, shift, start)) {
                continue;
            }
            for (int i = from; i < to; i++) {
                int p = from + start[(int) (srcK[i] >>> shift) & 0xff]++;
                dstK[p] = srcK[i];
                dstI[p] = srcI[i];
            }
            long[] k = srcK;
            srcK = dstK;
            dstK = k;
            int[] t = srcI;
            srcI = dstI;
            dstI = t;
        }
        if (srcK != keys) {
            System.arraycopy(srcK, from, keys, from, to - from);
            System.arraycopy(srcI, from, items, from, to - from);
        }
    }

    /**
     * Counts the keys by their byte at {@code shift} and turns the counts into each byte's first place.
     *
     * @return false if every key has the same byte there, so that the pass would move nothing
     */
    private static boolean count(long[] keys, int from, int to, int shift, int[] start) {
        Arrays.fill(start, 0);
        for (int i = from; i < to; i++) {
            start[((int) (keys[i] >>> shift) & 0xff) + 1]++;
        }
        if (start[((int) (keys[from] >>> shift) & 0xff) + 1] == to - from) {
            return false;
        }
        for (int b = 0; b < 256; b++) {
            start[b + 1] += start[b];
        }
        return true;
    }

    private static void insertion(long[] keys, int[] items, int from, int to) {
        for (int i = from + 1; i < to; i++) {
            long k = keys[i];
            int v = items[i];
            int j = i - 1;
            while (j >= from && Long.compareUnsigned(keys[j], k) > 0) {
                keys[j + 1] = keys[j];
                items[j + 1] = items[j];
                j--;
            }
            keys[j + 1] = k;
            items[j + 1] = v;
        }
    }
}
