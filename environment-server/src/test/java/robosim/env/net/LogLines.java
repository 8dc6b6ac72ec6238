package robosim.env.net;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

/** Keeps the warnings and info lines the server's loggers publish during a test. */
final class LogLines extends Handler implements AutoCloseable {
    private final Logger logger = Logger.getLogger("robosim.env.net");
    private final List<String> warnings = new ArrayList<>();
    private final List<String> infos = new ArrayList<>();

    LogLines() {
        logger.addHandler(this);
    }

    @Override
    public synchronized void publish(LogRecord r) {
        if (r.getLevel().intValue() >= Level.WARNING.intValue()) {
            warnings.add(r.getMessage());
        } else if (r.getLevel() == Level.INFO) {
            infos.add(r.getMessage());
        }
    }

    synchronized List<String> infos() {
        return new ArrayList<>(infos);
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
