package robosim.pioneer.server;

import java.util.concurrent.TimeUnit;

/**
 * How much of an ARIA client's input is read in a cycle: at most {@value #MAX_PACKETS} packets and
 * {@value #MAX_BYTES} bytes each {@value #CYCLE_MS} ms, some forty times what an ARIA program sends
 * (a few commands a cycle and a PULSE) and several times what a Pioneer's 115 200-baud serial line
 * carries. A client that sends more is read no faster: its session waits for the next cycle before
 * it reads again, so the client's own writes back up in its connection and it slows only itself,
 * never the run or the other robots. A client that has kept over its budget for {@value
 * #FLOODING_MS} ms (what it sent meanwhile would take it minutes to drain) is flooding: its session
 * ends, and the port is free for the next client.
 */
final class InputBudget {
    /** The cycle the budget is counted over, ms: a Pioneer's SIP cycle. */
    static final int CYCLE_MS = 100;
    /** The packets read in a cycle. */
    static final int MAX_PACKETS = 200;
    /** The bytes read in a cycle. */
    static final int MAX_BYTES = 8192;

    /** How long a client may keep over its budget before it counts as flooding, ms. */
    static final int FLOODING_MS = 5000;

    private static final long CYCLE_NANOS = TimeUnit.MILLISECONDS.toNanos(CYCLE_MS);

    private long cycleStarted;
    private long bytes;
    private long packets;
    /** When the client went over its budget and has stayed over since; −1 while it keeps to it. */
    private long overSince = -1;

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
            // a whole cycle within the budget
            cycleStarted = now;
            bytes = 0;
            packets = 0;
            overSince = -1;
        }
        bytes += readBytes;
        packets += readPackets;
        if (bytes < MAX_BYTES && packets < MAX_PACKETS) {
            return 0;
        }
        if (overSince < 0) {
            overSince = cycleStarted;
        }
        long wait = cycleStarted + CYCLE_NANOS - now;
        cycleStarted += CYCLE_NANOS; // what went over counts against the next cycle
        bytes = Math.max(0, bytes - MAX_BYTES);
        packets = Math.max(0, packets - MAX_PACKETS);
        return Math.max(0, wait);
    }

    /**
     * @param now {@link System#nanoTime()}
     * @return whether the client has kept over its budget for {@value #FLOODING_MS} ms
     */
    boolean flooding(long now) {
        return overSince >= 0 && now - overSince > TimeUnit.MILLISECONDS.toNanos(FLOODING_MS);
    }
}
