package robosim.env.net;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import robosim.protocol.Await;

/**
 * Keeps the warnings and info lines the server's loggers publish during a test. The count lines of
 * a {@link robosim.protocol.LogLimiter} are kept apart ({@link #counts()}): a limiter of an earlier
 * test may log its count during this one.
 */
final class LogLines extends Handler implements AutoCloseable {
    private final Logger logger = Logger.getLogger("robosim.env.net");
    private final List<String> warnings = new ArrayList<>();
    private final List<String> infos = new ArrayList<>();
    private final List<String> counts = new ArrayList<>();

    LogLines() {
        logger.addHandler(this);
    }

    @Override
    public synchronized void publish(LogRecord r) {
        if (r.getMessage().endsWith(", not logged one by one")) {
            counts.add(r.getMessage());
        } else if (r.getLevel().intValue() >= Level.WARNING.intValue()) {
            warnings.add(r.getMessage());
        } else if (r.getLevel() == Level.INFO) {
            infos.add(r.getMessage());
        }
    }

    synchronized List<String> infos() {
        return new ArrayList<>(infos);
    }

    /** @return the count lines of rate-limited kinds, in order */
    synchronized List<String> counts() {
        return new ArrayList<>(counts);
    }

    /**
     * Waits for a count line that starts so.
     *
     * @return it
     */
    String awaitCount(String start) {
        return Await.value(Duration.ofSeconds(10), "a count line '" + start + "...' (so far " + counts() + ")",
                () -> counts().stream().filter(line -> line.startsWith(start)).findFirst().orElse(null));
    }

    /**
     * Waits until the lines of a rate-limited kind account for so many events: each whole line
     * (a warning that starts so) for one, each count line of the kind for its count. However the
     * events fall into periods on a busy machine, that sum is the number of events (or more: a count
     * of an earlier test's limiter may come late, within this test).
     *
     * @param whole  how the kind's whole lines start
     * @param kind   the kind, as its count lines name it
     * @param events how many there were
     */
    void awaitAccounted(String whole, String kind, int events) {
        Await.until(Duration.ofSeconds(10), "lines accounting for " + events + " " + kind + " (so far " + warnings()
                + " and " + counts() + ")", () -> accounted(whole, kind) >= events);
    }

    private synchronized int accounted(String whole, String kind) {
        int n = (int) warnings.stream().filter(l -> l.startsWith(whole)).count();
        for (String c : counts) {
            if (c.contains(" more " + kind + " in the last ")) {
                n += Integer.parseInt(c.substring(0, c.indexOf(' ')));
            }
        }
        return n;
    }

    synchronized List<String> warnings() {
        return new ArrayList<>(warnings);
    }

    @Override
    public void flush() {
    }

    @Override
    public void close() {
        logger.removeHandler(this);
    }
}
