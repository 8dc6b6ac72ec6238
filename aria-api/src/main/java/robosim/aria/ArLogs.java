package robosim.aria;

import java.util.logging.Logger;

/** The log lines of the action classes, on the {@code robosim.aria} logger. */
final class ArLogs {
    private static final Logger LOG = Logger.getLogger("robosim.aria");

    private ArLogs() {
    }

    static void sanity(String action, String what, double value, String rule, int bound) {
        LOG.warning(() -> String.format("action '%s' set %s to %g, which would be %s %d; %d is used",
                action, what, value, rule, bound, bound));
    }

    static void info(String line) {
        LOG.info(line);
    }
}
