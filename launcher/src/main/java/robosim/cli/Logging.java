package robosim.cli;

import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.SimpleFormatter;

/** One-line log records on standard error, for every command. */
final class Logging {
    private Logging() {
    }

    static void configure() {
        if (System.getProperty("java.util.logging.SimpleFormatter.format") == null) {
            System.setProperty("java.util.logging.SimpleFormatter.format", "%1$tT %4$s %3$s: %5$s%6$s%n");
        }
        // the first line's time loads the time-zone rules from a file: load them now, not when the
        // line to write says that the file table is full
        new SimpleFormatter().format(new LogRecord(Level.INFO, "warm-up"));
    }
}
