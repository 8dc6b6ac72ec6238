package robosim.map;

import java.nio.file.Path;

/**
 * The heap a map takes to read into a world, checked before the work is done: from the header's
 * {@code NumPoints} and {@code NumLines} before the first section, and from what has been read
 * every {@value #CHECK_EVERY} items after, so that a map too large for this JVM is refused at once
 * with the option that helps, instead of running out of memory minutes later.
 *
 * <p>The figures are the worst case, measured: every point a square obstacle of its own (as
 * points scattered at random are), each line a wall; the store of the items, the merge's runs
 * and the obstacles all live at once. 3 000 000 random points read in a heap of 560 MB (not 500),
 * 2 000 000 lines in 380 MB; a scanned building, whose points merge, takes less.
 */
final class MapMemory {
    /** Heap per point at worst, bytes. */
    static final long POINT_BYTES = 200;
    /** Heap per line at worst, bytes. */
    static final long LINE_BYTES = 160;
    /** Heap besides the map's items, bytes. */
    static final long BASE_BYTES = 64L << 20;
    /** Items read between two checks. */
    static final int CHECK_EVERY = 1 << 20;

    private final Path file;
    private final long maxHeap;

    /**
     * @param file    the map file, for messages
     * @param maxHeap the most heap this JVM may use, bytes ({@link Runtime#maxMemory()})
     */
    MapMemory(Path file, long maxHeap) {
        this.file = file;
        this.maxHeap = maxHeap;
    }

    /** @return the heap, bytes, that reading {@code points} points and {@code lines} lines takes at worst */
    static long need(long points, long lines) {
        return BASE_BYTES + points * POINT_BYTES + lines * LINE_BYTES;
    }

    /**
     * @param points points to hold
     * @param lines  lines to hold
     * @param line   the file line to name
     * @param what   what says there are so many, for the message
     * @throws MapFileException if this JVM's heap cannot take them
     */
    void check(long points, long lines, int line, String what) {
        long need = need(points, lines);
        if (need <= maxHeap) {
            return;
        }
        long suggest = Math.max(1, (need * 5 / 4 + (1L << 30) - 1) >> 30);
        throw new MapFileException(file, line, what + " " + points + " points and " + lines + " lines, which may"
                + " take " + mb(need) + " MB of heap to read, but this Java may use " + mb(maxHeap) + " MB: give it"
                + " more with the -Xmx option (for bin/robosim: ROBOSIM_JAVA_OPTS=-Xmx" + suggest + "g bin/robosim"
                + " ...; for java: java -Xmx" + suggest + "g ...)");
    }

    private static long mb(long bytes) {
        return bytes >> 20;
    }
}
