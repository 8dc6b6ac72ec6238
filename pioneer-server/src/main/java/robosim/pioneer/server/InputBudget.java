package robosim.pioneer.server;

import java.util.concurrent.TimeUnit;

/**
 * How much of an ARIA client's input is read in a cycle: at most {@value #MAX_PACKETS} packets and
 * {@value #MAX_BYTES} bytes each {@value #CYCLE_MS} ms, some forty times what an ARIA program sends
 * (a few commands a cycle and a PULSE) and several times what a Pioneer's 115 200-baud serial line
 * carries. A client that sends more is read no faster: its session waits for the next cycle before
 * it reads again, so the client's own writes back up in its connection and it slows only itself,
 * never the run or the other robots.
 */
final class InputBudget {
    /** The cycle the budget is counted over, ms: a Pioneer's SIP cycle. */
    static final int CYCLE_MS = 100;
    /** The packets read in a cycle. */
    static final int MAX_PACKETS = 200;
    /** The bytes read in a cycle. */
    static final int MAX_BYTES = 8192;

    private static final long CYCLE_NANOS = TimeUnit.MILLISECONDS.toNanos(CYCLE_MS);

    private long cycleStarted;
    private long bytes;
    private long packets;
    private long heldBackCycles;

    /** @param now {@link System#nanoTime()} as the client connected */
    InputBudget(long now) {
        cycleStarted = now;
    }

    /**
     * Counts what a read brought.
     *
     * @param readBytes   bytes read
     * @param readPackets packets they made
     * @param now         {@link System#nanoTime()}
     * @return nanoseconds to wait before reading again: 0 within the budget, else until the cycle ends
     */
    long spent(int readBytes, int readPackets, long now) {
        if (now - cycleStarted >= CYCLE_NANOS) {
            cycleStarted = now;
            bytes = 0;
            packets = 0;
        }
        bytes += readBytes;
        packets += readPackets;
        if (bytes < MAX_BYTES && packets < MAX_PACKETS) {
            return 0;
        }
        heldBackCycles++;
        long wait = cycleStarted + CYCLE_NANOS - now;
        cycleStarted += CYCLE_NANOS; // what went over counts against the next cycle
        bytes = Math.max(0, bytes - MAX_BYTES);
        packets = Math.max(0, packets - MAX_PACKETS);
        return Math.max(0, wait);
    }

    /** @return the cycles in which the client sent more than the budget */
    long heldBackCycles() {
        return heldBackCycles;
    }
}
