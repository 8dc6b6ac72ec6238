package robosim.viewer.window;

import java.util.ArrayList;
import java.util.List;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.viewer.draw.Trails;

/**
 * What the window shows: the world, the current snapshot, the robots' trails, and where the snapshots
 * come from or why they stopped. Panels observe it and repaint when it changes. Used on the Swing
 * event thread only.
 */
public final class ViewModel {
    private final List<Runnable> observers = new ArrayList<>();
    private final Trails trails = new Trails();
    private WorldDescription world;
    private Snapshot snapshot;
    private String source = "";
    private String ended;

    /** @param observer called after every change */
    public void observe(Runnable observer) {
        observers.add(observer);
    }

    private void changed() {
        for (Runnable r : observers) {
            r.run();
        }
    }

    /**
     * A new world: the snapshot and the trails are forgotten.
     *
     * @param newWorld the world
     */
    public void world(WorldDescription newWorld) {
        world = newWorld;
        snapshot = null;
        trails.clear();
        changed();
    }

    /**
     * The next snapshots of a live run, in order: each extends the trails, the last is shown.
     *
     * @param snapshots the snapshots, oldest first; none is ignored
     */
    public void snapshots(List<Snapshot> snapshots) {
        if (snapshots.isEmpty()) {
            return;
        }
        for (Snapshot f : snapshots) {
            trails.add(f);
        }
        snapshot = snapshots.get(snapshots.size() - 1);
        changed();
    }

    /**
     * Shows a snapshot out of order, as a replay does when it jumps: the trails are rebuilt from the
     * snapshots that lead up to it.
     *
     * @param history the snapshots from the start up to and including the one to show
     */
    public void jump(List<Snapshot> history) {
        trails.clear();
        for (Snapshot f : history) {
            trails.add(f);
        }
        snapshot = history.isEmpty() ? null : history.get(history.size() - 1);
        changed();
    }

    /**
     * @param text where the snapshots come from, such as {@code live from localhost:3000}
     */
    public void source(String text) {
        source = text;
        changed();
    }

    /**
     * The snapshots have stopped coming.
     *
     * @param reason why, such as the Environment's goodbye
     */
    public void ended(String reason) {
        ended = reason;
        changed();
    }

    /** @return the world, or {@code null} before it has come */
    public WorldDescription world() {
        return world;
    }

    /** @return the snapshot shown, or {@code null} */
    public Snapshot snapshot() {
        return snapshot;
    }

    /** @return the robots' paths up to the snapshot shown */
    public Trails trails() {
        return trails;
    }

    /** @return where the snapshots come from */
    public String source() {
        return source;
    }

    /** @return why the snapshots stopped, or {@code null} while they come */
    public String endedReason() {
        return ended;
    }
}
