package robosim.scout;

import java.util.Arrays;

/**
 * The Scout's sonar firing schedule ({@link Scout#conf_sn}), emulated on the client from the
 * Environment's readings, which cover all sixteen sonars every step.
 *
 * <p>The rule, exactly: a configuration made when the latest state's simulated time is {@code c}
 * fires its k-th sonar (k = 0, 1, 2, ...) at {@code c + (k + 1) · rate · 4} ms, and that firing is
 * sonar {@code order[k mod n]}. When a state of time {@code T} arrives, every firing at a time in
 * (time of the previous state, {@code T}] happens, in order, and takes that sonar's range from this
 * state. A sonar that fires while the sonars are off (the state has no readings) keeps its value;
 * a sonar not in the order never changes. Before its first firing a sonar reads 255 inches.
 */
final class SonarSchedule {
    /** The default: every sonar, in order, at the fastest rate. */
    static final int[] ALL = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
    /** One rate unit, ms. */
    static final long RATE_UNIT_MS = 4;

    private final long[] inches = new long[StateVector.SONARS];
    private int[] order = ALL;
    private long periodMs = RATE_UNIT_MS;
    private long nextMs;
    private int next;

    /** @param nowMs simulated time the default schedule starts from */
    SonarSchedule(long nowMs) {
        Arrays.fill(inches, NomadUnits.MAX_SONAR_INCHES);
        nextMs = nowMs + periodMs;
    }

    /**
     * Reads a firing order as the C library does: sonar numbers 0..15, ended by 255 or by the 16th
     * entry (or the array's end).
     *
     * @param order the order
     * @return the sonars in firing order, possibly none; null if an entry before the end is not a
     *         sonar number
     */
    static int[] parseOrder(int[] order) {
        if (order == null) {
            return null;
        }
        int n = 0;
        while (n < Math.min(order.length, StateVector.SONARS) && order[n] != StateVector.ORDER_END) {
            if (order[n] < 0 || order[n] >= StateVector.SONARS) {
                return null;
            }
            n++;
        }
        return Arrays.copyOf(order, n);
    }

    /**
     * Starts a new schedule.
     *
     * @param rate   the firing period in 4 ms units, at least 1
     * @param sonars the parsed firing order (see {@link #parseOrder}); empty fires nothing
     * @param nowMs  simulated time of the latest state
     */
    void configure(int rate, int[] sonars, long nowMs) {
        order = sonars.clone();
        periodMs = rate * RATE_UNIT_MS;
        next = 0;
        nextMs = nowMs + periodMs;
    }

    /** @return whether any sonar fires */
    boolean firesAny() {
        return order.length > 0;
    }

    /**
     * Runs the firings due up to a new state.
     *
     * @param timeMs  the state's simulated time
     * @param rangeMm the state's sonar ranges in mm, by sonar number; empty when the sonars are off
     */
    void observe(long timeMs, int[] rangeMm) {
        if (order.length == 0 || timeMs < nextMs) {
            return;
        }
        long due = (timeMs - nextMs) / periodMs + 1;
        if (due > order.length) {
            // only the last n firings can still show: each sonar's latest one is among them
            long skip = due - order.length;
            next = (int) ((next + skip) % order.length);
            nextMs += skip * periodMs;
            due = order.length;
        }
        for (long k = 0; k < due; k++) {
            int sonar = order[next];
            if (sonar < rangeMm.length) {
                inches[sonar] = NomadUnits.sonarMmToInches(rangeMm[sonar]);
            }
            next = (next + 1) % order.length;
            nextMs += periodMs;
        }
    }

    /**
     * @param sonar a sonar number, 0..15
     * @return its latest firing's range, inches
     */
    long inches(int sonar) {
        return inches[sonar];
    }
}
