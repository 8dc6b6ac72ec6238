package robosim.protocol.recording;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Objects;
import java.util.logging.Logger;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/**
 * Passes each call on to several listeners, in the order they were added. A listener that fails
 * is logged (naming it, the step and the reason), closed and dropped; the others go on, and so
 * does the run that feeds them. Not thread-safe: one feeder at a time.
 */
public final class SnapshotListeners implements SnapshotListener {
    private static final Logger LOG = Logger.getLogger(SnapshotListeners.class.getName());

    private final List<SnapshotListener> listeners = new ArrayList<>();
    private long step = -1;

    /** A call on a listener, which may fail. */
    private interface Call {
        void on(SnapshotListener listener) throws IOException;
    }

    /** @param listener a listener to follow the run from now on */
    public void add(SnapshotListener listener) {
        listeners.add(Objects.requireNonNull(listener, "listener"));
    }

    /** @return how many listeners are still following */
    public int size() {
        return listeners.size();
    }

    @Override
    public void world(WorldDescription world) {
        tell(l -> l.world(world));
    }

    @Override
    public void snapshot(Snapshot snapshot) {
        step = snapshot.step();
        tell(l -> l.snapshot(snapshot));
    }

    @Override
    public void end(String reason) {
        tell(l -> l.end(reason));
    }

    /** Closes every listener and forgets them; a failure to close is logged. */
    @Override
    public void close() {
        for (SnapshotListener listener : listeners) {
            closeQuietly(listener);
        }
        listeners.clear();
    }

    private void tell(Call call) {
        for (Iterator<SnapshotListener> it = listeners.iterator(); it.hasNext(); ) {
            SnapshotListener listener = it.next();
            try {
                call.on(listener);
            } catch (IOException | RuntimeException e) {
                LOG.severe("snapshot listener " + listener + " failed after step " + step + " and is dropped: "
                        + e.getMessage());
                it.remove();
                closeQuietly(listener);
            }
        }
    }

    private static void closeQuietly(SnapshotListener listener) {
        try {
            listener.close();
        } catch (IOException | RuntimeException e) {
            LOG.severe("closing snapshot listener " + listener + " failed: " + e.getMessage());
        }
    }
}
