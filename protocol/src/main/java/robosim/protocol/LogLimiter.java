package robosim.protocol;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import java.util.function.Supplier;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Log lines that input from outside can cause (a peer's bytes, a file's content), held to one line
 * per kind a period: the first of a period is logged whole, the rest only counted, and the count is
 * logged as one line when the period ends. So a client that sends a million bad packets costs a line
 * a second, not a million lines, and never the disk. A kind is a fixed description chosen by the
 * code, never text from the input ("dropped packets from robot r1's ARIA client"); quote the input in
 * the line only as {@link #excerpt(String)} gives it.
 *
 * <p>Safe to use from any thread. The counts of a flood's last period are logged by a daemon thread
 * shared by every limiter, when the period ends, whether or not more lines come.
 */
public final class LogLimiter {
    /** The default period: one line a second for each kind. */
    public static final long PERIOD_MS = 1000;
    /** The characters of input an {@link #excerpt(String)} keeps. */
    public static final int EXCERPT_CHARS = 60;

    private static final class Holder {
        static final ScheduledExecutorService FLUSHER = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "robosim-log-limiter");
            t.setDaemon(true);
            return t;
        });
    }

    /** A kind's period: when it ends, and what has been counted in it. */
    private static final class Period {
        long endsNanos;
        long suppressed;
        Level level;
        boolean scheduled;
    }

    private final Logger log;
    private final long periodNanos;
    private final LongSupplier clock;
    private final boolean scheduleFlush;
    private final Map<String, Period> periods = new HashMap<>();

    /**
     * A limiter of one line per kind a second.
     *
     * @param log where the lines go
     */
    public LogLimiter(Logger log) {
        this(log, PERIOD_MS, System::nanoTime, true);
    }

    /**
     * A limiter of one line per kind a period.
     *
     * @param log      where the lines go
     * @param periodMs the shortest time between two whole lines of a kind
     */
    public LogLimiter(Logger log, long periodMs) {
        this(log, periodMs, System::nanoTime, true);
    }

    /**
     * @param log           where the lines go
     * @param periodMs      the shortest time between two whole lines of a kind
     * @param clock         {@link System#nanoTime()}, or a test's clock
     * @param scheduleFlush whether the counts are logged when a period ends by themselves (false: only
     *                      by {@link #flush()} and the next line of the kind)
     */
    LogLimiter(Logger log, long periodMs, LongSupplier clock, boolean scheduleFlush) {
        this.log = log;
        this.periodNanos = TimeUnit.MILLISECONDS.toNanos(periodMs);
        this.clock = clock;
        this.scheduleFlush = scheduleFlush;
    }

    /**
     * Logs the line now if none of its kind was logged this period, else counts it.
     *
     * @param level the line's level
     * @param kind  what lines of this kind are about, fixed by the code: it names the count's line
     * @param line  the line, made only when it is logged
     * @return whether it was logged
     */
    public boolean log(Level level, String kind, Supplier<String> line) {
        if (!log.isLoggable(level)) {
            return false;
        }
        List<Runnable> counts;
        boolean whole;
        synchronized (this) {
            long now = clock.getAsLong();
            counts = endPeriods(now);
            Period p = periods.get(kind);
            whole = p == null;
            if (whole) {
                p = new Period();
                p.endsNanos = now + periodNanos;
                periods.put(kind, p);
            } else {
                p.suppressed++;
                p.level = level;
                if (scheduleFlush && !p.scheduled) {
                    p.scheduled = true;
                    Holder.FLUSHER.schedule(this::flush, Math.max(0, p.endsNanos - now), TimeUnit.NANOSECONDS);
                }
            }
        }
        counts.forEach(Runnable::run);
        if (whole) {
            log.logp(level, log.getName(), null, line); // the source is the logger, not this class
        }
        return whole;
    }

    /**
     * @param kind what the lines are about
     * @param line the warning
     * @return whether it was logged
     * @see #log(Level, String, Supplier)
     */
    public boolean warning(String kind, Supplier<String> line) {
        return log(Level.WARNING, kind, line);
    }

    /**
     * @param kind what the lines are about
     * @param line the line
     * @return whether it was logged
     * @see #log(Level, String, Supplier)
     */
    public boolean info(String kind, Supplier<String> line) {
        return log(Level.INFO, kind, line);
    }

    /** Logs the counts of every kind whose period has ended. */
    public void flush() {
        List<Runnable> counts;
        synchronized (this) {
            counts = endPeriods(clock.getAsLong());
        }
        counts.forEach(Runnable::run);
    }

    /**
     * @param kind what the lines are about
     * @return how many lines of the kind have been counted this period and not logged yet
     */
    public synchronized long suppressed(String kind) {
        Period p = periods.get(kind);
        return p == null ? 0 : p.suppressed;
    }

    /**
     * Ends the periods that are over: a period in which lines were counted has its count logged and
     * starts another at once, so a flood goes on costing one line a period; one without ends.
     *
     * @return the count lines to log, once the lock is let go
     */
    private List<Runnable> endPeriods(long now) {
        List<Runnable> counts = new ArrayList<>();
        for (Iterator<Map.Entry<String, Period>> it = periods.entrySet().iterator(); it.hasNext(); ) {
            Map.Entry<String, Period> e = it.next();
            Period p = e.getValue();
            if (now - p.endsNanos < 0) {
                continue;
            }
            if (p.suppressed == 0) {
                it.remove();
                continue;
            }
            String line = p.suppressed + " more " + e.getKey() + " in the last "
                    + TimeUnit.NANOSECONDS.toMillis(periodNanos) + " ms, not logged one by one";
            Level level = p.level;
            counts.add(() -> log.logp(level, log.getName(), null, line));
            p.suppressed = 0;
            p.scheduled = false;
            p.endsNanos = now + periodNanos;
        }
        return counts;
    }

    /**
     * Input as it may be quoted in a log line or an error: at most {@value #EXCERPT_CHARS}
     * characters, anything outside printable ASCII escaped as a backslash, u and four hex digits, and the whole length
     * said when it is cut, so that no input can forge a line, reach the terminal or fill the disk.
     *
     * @param text the input, or null
     * @return the excerpt
     */
    public static String excerpt(String text) {
        return RobotHello.printable(text, EXCERPT_CHARS);
    }
}
