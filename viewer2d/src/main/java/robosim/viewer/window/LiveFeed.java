package robosim.viewer.window;

import java.util.ArrayList;
import java.util.List;
import javax.swing.SwingUtilities;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;

/**
 * Carries a live run from the network thread to a {@link ViewModel} on the Swing event thread, in
 * order. What arrives faster than the window paints is gathered and handed over together, so a
 * fast run never floods the event queue, and every snapshot still extends the trails.
 */
public final class LiveFeed implements SnapshotListener {
    private final ViewModel model;
    private final List<Object> pending = new ArrayList<>();
    private boolean scheduled;

    /** The end of the feed, with the reason to show. */
    private record Ended(String reason, boolean orderly) { }

    /** @param model the window's model */
    public LiveFeed(ViewModel model) {
        this.model = model;
    }

    @Override
    public void world(WorldDescription world) {
        post(world);
    }

    @Override
    public void snapshot(Snapshot snapshot) {
        post(snapshot);
    }

    @Override
    public void end(String reason) {
        post(new Ended(reason, true));
    }

    @Override
    public void close() {
        post(new Ended("the connection ended", false));
    }

    private void post(Object event) {
        synchronized (pending) {
            pending.add(event);
            if (scheduled) {
                return;
            }
            scheduled = true;
        }
        SwingUtilities.invokeLater(this::deliver);
    }

    /** On the event thread: applies what has arrived, in order, a run of snapshots at a time. */
    private void deliver() {
        List<Object> events;
        synchronized (pending) {
            events = new ArrayList<>(pending);
            pending.clear();
            scheduled = false;
        }
        List<Snapshot> snapshots = new ArrayList<>();
        for (Object e : events) {
            if (e instanceof Snapshot f) {
                snapshots.add(f);
                continue;
            }
            model.snapshots(snapshots);
            snapshots = new ArrayList<>();
            if (e instanceof WorldDescription w) {
                model.world(w);
            } else if (e instanceof Ended end && (end.orderly() || model.endedReason() == null)) {
                model.ended(end.reason());
            }
        }
        model.snapshots(snapshots);
    }
}
