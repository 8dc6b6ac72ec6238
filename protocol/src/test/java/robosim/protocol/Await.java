package robosim.protocol;

import java.time.Duration;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

/**
 * Waiting in a test for a condition that another thread, process or peer makes true: the condition
 * is polled (every millisecond at first, then at most every {@value #MAX_POLL_MS} ms) until it holds
 * or the deadline passes. A test waits on what it needs, never for a fixed time; the deadline only
 * bounds a failing test, so it is generous for a busy machine.
 *
 * <p>Where the waiting thread can be told instead (a latch, a future, a blocking queue), that is
 * better still; this is for state that can only be looked at.
 */
public final class Await {
    /** The deadline when a test names none. */
    public static final Duration PATIENCE = Duration.ofSeconds(30);
    /** The longest pause between two looks at the condition, ms. */
    public static final long MAX_POLL_MS = 10;

    private Await() {
    }

    /**
     * Waits until the condition holds, at most {@link #PATIENCE}.
     *
     * @param what      what the test waits for, for the failure's message
     * @param condition the condition
     * @throws AssertionError if it does not hold in time
     */
    public static void until(String what, BooleanSupplier condition) {
        until(PATIENCE, what, condition);
    }

    /**
     * Waits until the condition holds.
     *
     * @param timeout   the longest wait
     * @param what      what the test waits for, for the failure's message
     * @param condition the condition
     * @throws AssertionError if it does not hold in time
     */
    public static void until(Duration timeout, String what, BooleanSupplier condition) {
        if (!within(timeout, condition)) {
            throw new AssertionError("not within " + timeout.toMillis() + " ms: " + what);
        }
    }

    /**
     * Waits until the condition holds, or the time is up.
     *
     * @param timeout   the longest wait
     * @param condition the condition
     * @return whether it held in time
     */
    public static boolean within(Duration timeout, BooleanSupplier condition) {
        return value(timeout, () -> condition.getAsBoolean() ? Boolean.TRUE : null) != null;
    }

    /**
     * Waits until the probe gives a value.
     *
     * @param <T>     the value's type
     * @param timeout the longest wait
     * @param what    what the test waits for, for the failure's message
     * @param probe   gives the value, or null while there is none yet
     * @return the first value the probe gave
     * @throws AssertionError if it gives none in time
     */
    public static <T> T value(Duration timeout, String what, Supplier<T> probe) {
        T v = value(timeout, probe);
        if (v == null) {
            throw new AssertionError("not within " + timeout.toMillis() + " ms: " + what);
        }
        return v;
    }

    private static <T> T value(Duration timeout, Supplier<T> probe) {
        long deadline = System.nanoTime() + timeout.toNanos();
        long pauseMs = 1;
        while (true) {
            T v = probe.get();
            if (v != null || System.nanoTime() - deadline >= 0) {
                return v;
            }
            pause(pauseMs);
            pauseMs = Math.min(MAX_POLL_MS, pauseMs * 2);
        }
    }

    private static void pause(long ms) {
        try {
            Thread.sleep(ms); // the poll's interval, between two looks at the condition
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError("interrupted while waiting", e);
        }
    }
}
