package robosim.env.net;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import java.util.logging.SimpleFormatter;
import robosim.protocol.LogLine;

/**
 * The Environment's log lines for the control clients that follow them (a {@code log} request): a
 * ControlPanel attached to an Environment it did not start shows them in its log pane. A handler
 * on RoboSim's loggers keeps every line of INFO and above, from any thread, in a bounded queue; the
 * step loop sends them on between two messages, on its own thread as every send. Lines that find
 * the queue full are counted and said in one line when there is room again. With no follower the
 * queue is emptied, so nothing builds up.
 */
final class LogForwarding implements AutoCloseable {
    /** The logger whose lines (and those of every logger below it) are forwarded. */
    static final String LOGGER = "robosim";
    /** The most lines waiting to be sent. */
    static final int MAX_QUEUED = 1000;

    /** A line logged and not yet sent. */
    private record Line(String level, String text) { }

    private final ConcurrentLinkedQueue<Line> queue = new ConcurrentLinkedQueue<>();
    private final AtomicInteger queued = new AtomicInteger();
    private final AtomicInteger dropped = new AtomicInteger();
    private final List<Connection> followers = new ArrayList<>();
    private final Handler handler = new Handler() {
        private final SimpleFormatter formatter = new SimpleFormatter();

        @Override
        public void publish(LogRecord record) {
            if (record.getLevel().intValue() < Level.INFO.intValue()) {
                return;
            }
            if (queued.incrementAndGet() > MAX_QUEUED) {
                queued.decrementAndGet();
                dropped.incrementAndGet();
                return;
            }
            String level = record.getLevel().intValue() >= Level.SEVERE.intValue() ? "SEVERE"
                    : record.getLevel().intValue() >= Level.WARNING.intValue() ? "WARNING" : "INFO";
            String text = formatter.formatMessage(record);
            if (record.getThrown() != null) {
                text += ": " + record.getThrown();
            }
            String source = record.getLoggerName() == null ? "" : record.getLoggerName()
                    .substring(record.getLoggerName().lastIndexOf('.') + 1) + ": ";
            queue.add(new Line(level, cut(source + text)));
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    };

    /** Starts keeping RoboSim's log lines. */
    void install() {
        Logger.getLogger(LOGGER).addHandler(handler);
    }

    /**
     * A control client asked for the log: from now it is sent every line.
     *
     * @param c the client
     */
    void follow(Connection c) {
        if (!followers.contains(c)) {
            followers.add(c);
        }
    }

    /**
     * Sends the lines kept since the last call to every follower still connected; called by the
     * step loop's thread.
     *
     * @param step the last step run
     */
    void forward(long step) {
        if (queue.isEmpty() && dropped.get() == 0) {
            return; // the step loop calls this at every wake-up: nothing to do is the common case
        }
        followers.removeIf(Connection::isClosed);
        int lost = dropped.getAndSet(0);
        List<LogLine> lines = new ArrayList<>();
        for (Line l = queue.poll(); l != null; l = queue.poll()) {
            queued.decrementAndGet();
            lines.add(new LogLine(step, l.level(), l.text()));
        }
        if (lost > 0) {
            lines.add(new LogLine(step, "WARNING", lost + " log lines were not forwarded: more than "
                    + MAX_QUEUED + " came between two sends"));
        }
        for (Connection c : followers) {
            for (LogLine line : lines) {
                c.send(line);
            }
        }
    }

    /** Stops keeping log lines. */
    @Override
    public void close() {
        Logger.getLogger(LOGGER).removeHandler(handler);
        queue.clear();
        queued.set(0);
    }

    private static String cut(String text) {
        return text.length() <= LogLine.MAX_TEXT ? text : text.substring(0, LogLine.MAX_TEXT - 1) + "…";
    }
}
