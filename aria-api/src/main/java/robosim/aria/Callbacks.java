package robosim.aria;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * One of {@link ArRobot}'s callback lists (connect, failed connect, disconnect normally, disconnect
 * on error, run exit, stabilizing), with ARIA's rules ({@code ArRobot::addConnectCB} and its kin,
 * ArRobot.cpp): {@link ArListPos#FIRST} puts a callback at the front, {@link ArListPos#LAST} at the
 * back, any other position is refused with a log line; removing takes out the first copy. A callback
 * that throws is logged and the others still run.
 */
final class Callbacks {
    private static final Logger LOG = Logger.getLogger(ArRobot.class.getName());

    private final String what;
    private final List<Runnable> list = new ArrayList<>();

    /** @param what ARIA's name of the add call, for the log lines (for example {@code addConnectCB}) */
    Callbacks(String what) {
        this.what = what;
    }

    synchronized void add(Runnable callback, int position) {
        if (callback == null) {
            LOG.warning(() -> "ArRobot::" + what + ": no callback given, ignoring it");
        } else if (position == ArListPos.FIRST) {
            list.add(0, callback);
        } else if (position == ArListPos.LAST) {
            list.add(callback);
        } else {
            LOG.warning(() -> "ArRobot::" + what + ": Invalid position " + position + ", as ARIA says; ignoring it");
        }
    }

    synchronized void remove(Runnable callback) {
        list.remove(callback);
    }

    synchronized List<Runnable> copy() {
        return List.copyOf(list);
    }

    /** Runs every callback, in list order, outside the list's lock. */
    void invoke(String robot) {
        for (Runnable r : copy()) {
            try {
                r.run();
            } catch (RuntimeException e) {
                LOG.log(Level.WARNING, "robot " + robot + ": a " + what + " callback threw", e);
            }
        }
    }
}
