package robosim.env.net;

import java.util.function.Supplier;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * A warning that may repeat many times a second (a failing {@code accept}, connections refused
 * over a cap) logged at most once a period: the first occurrence is logged whole, the rest of the
 * period only counted, and the count is logged when the period ends, so that a flood of failures
 * costs one line a period instead of filling the disk.
 */
final class RateLimitedLog {
    private final Logger log;
    private final String what;
    private final long periodNanos;
    private long periodEnds;
    private boolean inPeriod;
    private long suppressed;

    /**
     * @param log         where the lines go
     * @param what        what is counted, plural, for the count's line: "accept failures"
     * @param periodNanos the shortest time between two lines
     */
    RateLimitedLog(Logger log, String what, long periodNanos) {
        this.log = log;
        this.what = what;
        this.periodNanos = periodNanos;
    }

    /**
     * Logs the line now if no line was logged this period, else counts it.
     *
     * @param now  {@link System#nanoTime()}
     * @param line the warning
     */
    void warn(long now, Supplier<String> line) {
        flush(now);
        if (inPeriod) {
            suppressed++;
            return;
        }
        log.warning(line);
        inPeriod = true;
        periodEnds = now + periodNanos;
    }

    /**
     * Logs how many were counted once the period has ended; call it now and then even when nothing
     * fails, so that the count of a flood's last period is not lost.
     *
     * @param now {@link System#nanoTime()}
     */
    void flush(long now) {
        if (!inPeriod || now - periodEnds < 0) {
            return;
        }
        if (suppressed > 0) {
            long n = suppressed;
            log.log(Level.WARNING, () -> n + " more " + what + " in the last " + periodNanos / 1_000_000
                    + " ms were not logged one by one");
        }
        inPeriod = false;
        suppressed = 0;
    }

    /** @return how many have been counted and not yet logged */
    long suppressed() {
        return suppressed;
    }
}
