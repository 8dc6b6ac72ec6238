package robosim.cli;

import java.util.concurrent.TimeUnit;

/**
 * When a plain line about a wait is due: the first after {@link #FIRST_S} s of waiting (a wait
 * shorter than that says nothing), then every {@link #EVERY_S} s for the first minute, then every
 * {@link #LATER_EVERY_S} s, so that a long wait writes few lines to a log.
 */
final class WaitSchedule {
    static final long FIRST_S = 2;
    static final long EVERY_S = 5;
    static final long LATER_EVERY_S = 30;
    private static final long MINUTE = TimeUnit.SECONDS.toNanos(60);

    private long nextNanos = TimeUnit.SECONDS.toNanos(FIRST_S);

    /**
     * @param waitedNanos how long the wait has lasted
     * @return whether a line is due now; if so, the next is due one period later
     */
    boolean due(long waitedNanos) {
        if (waitedNanos < nextNanos) {
            return false;
        }
        long every = TimeUnit.SECONDS.toNanos(waitedNanos < MINUTE ? EVERY_S : LATER_EVERY_S);
        nextNanos = waitedNanos + every;
        return true;
    }

    /** Starts over, for a new wait. */
    void reset() {
        nextNanos = TimeUnit.SECONDS.toNanos(FIRST_S);
    }

    /** @return whole seconds, as the lines say them */
    static long seconds(long nanos) {
        return TimeUnit.NANOSECONDS.toSeconds(nanos);
    }
}
