package robosim.protocol;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

/**
 * The lines a logger tree publishes while a test runs: attach it in a try-with-resources (or open it
 * before each test and close it after), and read {@link #lines()}.
 */
public final class CapturedLog extends Handler implements AutoCloseable {
    private final Logger logger;
    private final List<String> lines = new ArrayList<>();

    /** @param name the logger whose lines (and its children's) are kept */
    public CapturedLog(String name) {
        logger = Logger.getLogger(name);
        logger.addHandler(this);
    }

    @Override
    public synchronized void publish(LogRecord r) {
        lines.add(r.getMessage());
    }

    /** @return the lines so far, in order */
    public synchronized List<String> lines() {
        return new ArrayList<>(lines);
    }

    /** Forgets the lines so far. */
    public synchronized void clear() {
        lines.clear();
    }

    @Override
    public void flush() {
    }

    @Override
    public void close() {
        logger.removeHandler(this);
    }
}
