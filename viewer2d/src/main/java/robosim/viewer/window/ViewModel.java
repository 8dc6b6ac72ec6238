package robosim.viewer.window;

import java.util.ArrayList;
import java.util.List;
import robosim.protocol.ViewerFrame;
import robosim.protocol.WorldDescription;
import robosim.viewer.Trails;

/**
 * What the window shows: the world, the current frame, the robots' trails, and where the frames
 * come from or why they stopped. Panels observe it and repaint when it changes. Used on the Swing
 * event thread only.
 */
public final class ViewModel {
    private final List<Runnable> observers = new ArrayList<>();
    private final Trails trails = new Trails();
    private WorldDescription world;
    private ViewerFrame frame;
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
     * A new world: the frame and the trails are forgotten.
     *
     * @param newWorld the world
     */
    public void world(WorldDescription newWorld) {
        world = newWorld;
        frame = null;
        trails.clear();
        changed();
    }

    /**
     * The next frames of a live run, in order: each extends the trails, the last is shown.
     *
     * @param frames the frames, oldest first; none is ignored
     */
    public void frames(List<ViewerFrame> frames) {
        if (frames.isEmpty()) {
            return;
        }
        for (ViewerFrame f : frames) {
            trails.add(f);
        }
        frame = frames.get(frames.size() - 1);
        changed();
    }

    /**
     * Shows a frame out of order, as a replay does when it jumps: the trails are rebuilt from the
     * frames that lead up to it.
     *
     * @param history the frames from the start up to and including the one to show
     */
    public void jump(List<ViewerFrame> history) {
        trails.clear();
        for (ViewerFrame f : history) {
            trails.add(f);
        }
        frame = history.isEmpty() ? null : history.get(history.size() - 1);
        changed();
    }

    /**
     * @param text where the frames come from, such as {@code live from localhost:3000}
     */
    public void source(String text) {
        source = text;
        changed();
    }

    /**
     * The frames have stopped coming.
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

    /** @return the frame shown, or {@code null} */
    public ViewerFrame frame() {
        return frame;
    }

    /** @return the robots' paths up to the frame shown */
    public Trails trails() {
        return trails;
    }

    /** @return where the frames come from */
    public String source() {
        return source;
    }

    /** @return why the frames stopped, or {@code null} while they come */
    public String endedReason() {
        return ended;
    }
}
