package robosim.viewer.window;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.Locale;
import java.util.List;
import robosim.protocol.MessageDelivery;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.viewer.draw.Departures;
import robosim.viewer.draw.Drawings;
import robosim.viewer.draw.Trails;

/**
 * What the window shows: the world, the current snapshot, the robots' trails, and where the snapshots
 * come from or why they stopped. Panels observe it and repaint when it changes. Used on the Swing
 * event thread only.
 */
public final class ViewModel {
    private final List<Runnable> observers = new ArrayList<>();
    private final Trails trails = new Trails();
    private final Drawings drawings = new Drawings();
    private final Departures departures = new Departures();
    private WorldDescription world;
    private Snapshot snapshot;
    private final Deque<String> messages = new ArrayDeque<>();
    private String source = "";
    private String ended;
    private String selected;
    private double[] cursor;

    /** How many of the latest messages are kept for the robot panel. */
    public static final int MESSAGES_KEPT = 50;

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
     * A new world: the snapshot, the trails and the drawings are forgotten, and so is why the
     * snapshots stopped before (a viewer that attaches again gets the world first).
     *
     * @param newWorld the world
     */
    public void world(WorldDescription newWorld) {
        world = newWorld;
        snapshot = null;
        ended = null;
        trails.clear();
        drawings.clear();
        departures.clear();
        messages.clear();
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
            drawings.add(f);
            departures.add(f);
            keepMessages(f);
        }
        snapshot = departures.over(drawings.over(snapshots.get(snapshots.size() - 1)));
        changed();
    }

    /**
     * Shows a snapshot out of order, as a replay does when it jumps: the trails and the drawings are
     * rebuilt from the snapshots that lead up to it.
     *
     * @param history the snapshots from the start up to and including the one to show
     */
    public void jump(List<Snapshot> history) {
        trails.clear();
        drawings.clear();
        departures.clear();
        messages.clear();
        for (Snapshot f : history) {
            trails.add(f);
            drawings.add(f);
            departures.add(f);
            keepMessages(f);
        }
        snapshot = history.isEmpty() ? null : departures.over(drawings.over(history.get(history.size() - 1)));
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

    /**
     * Keeps the snapshot's messages, speech, joins and departures and a robot's request to end the
     * run, each as one line naming the step and who.
     */
    private void keepMessages(Snapshot f) {
        for (MessageDelivery m : f.messages()) {
            keep(String.format(Locale.ROOT, "step %d: %s to %s: %s %s", f.step(), m.from(),
                    m.to() == null || m.to().isEmpty() ? "all" : m.to(), m.kind(), m.body()));
        }
        for (Snapshot.Said said : f.said()) {
            keep(String.format(Locale.ROOT, "step %d: %s said \"%s\"", f.step(), said.robot(), said.text()));
        }
        // joins and departures read as the run report says them, so a window shows who came and went
        for (Snapshot.Event e : f.events()) {
            keep(String.format(Locale.ROOT, "step %d: robot %s %s%s", e.step(), e.robot(), e.what(),
                    e.reason().isEmpty() ? "" : ": " + e.reason()));
        }
        // metrics are many and for the results: only the request that ends the run is a line
        Snapshot.EndRequest end = f.endRequest();
        if (end != null) {
            keep(String.format(Locale.ROOT, "step %d: robot %s ended the run: %s", end.step(), end.robot(),
                    end.reason()));
        }
    }

    private void keep(String line) {
        messages.addLast(line);
        while (messages.size() > MESSAGES_KEPT) {
            messages.removeFirst();
        }
    }

    /**
     * Chooses the robot whose panel is shown, as a click on it does.
     *
     * @param name the robot's name, or {@code null} for none
     */
    public void select(String name) {
        selected = name;
        changed();
    }

    /** @return the robot whose panel is shown, or {@code null} */
    public String selected() {
        return selected;
    }

    /**
     * Where the mouse is over the 2D world.
     *
     * @param xy the world point in mm, {x, y}, or {@code null} when the mouse is off the world
     */
    public void cursor(double[] xy) {
        cursor = xy == null ? null : xy.clone();
        changed();
    }

    /** @return the world point under the mouse in mm, {x, y}, or {@code null} */
    public double[] cursor() {
        return cursor == null ? null : cursor.clone();
    }

    /**
     * The latest messages sent and things said, oldest first, at most {@value #MESSAGES_KEPT}, such
     * as {@code step 120: r1 to r2: wall 3 4}.
     *
     * @return the lines
     */
    public List<String> messages() {
        return List.copyOf(messages);
    }

    /** @return the world, or {@code null} before it has come */
    public WorldDescription world() {
        return world;
    }

    /**
     * @return the snapshot shown, carrying every robot's current drawings and the departures of the
     *         robots gone (see {@link Departures#over}), or {@code null}
     */
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
