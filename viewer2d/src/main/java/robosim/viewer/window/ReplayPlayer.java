package robosim.viewer.window;

import java.util.ArrayList;
import java.util.List;
import javax.swing.Timer;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.Recording;

/**
 * Plays a recording into a {@link ViewModel}: play and pause, a step either way, a jump to any
 * step, at a speed relative to simulated time. A Swing timer drives playing; at speeds where a
 * step lasts less than {@value #MIN_TICK_MS} ms a tick moves on several steps. Used on the Swing
 * event thread only.
 */
public final class ReplayPlayer {
    /** The speeds offered, as multiples of real time. */
    public static final double[] SPEEDS = {0.25, 0.5, 1, 2, 4, 8, 16, 64};
    /** The shortest time between two timer ticks, ms. */
    public static final int MIN_TICK_MS = 20;

    private final List<Recording.Step> steps;
    private final ViewModel model;
    private final Timer timer;
    private final List<Runnable> observers = new ArrayList<>();
    private int index = -1;
    private double speed = 1;
    private int stepsPerTick = 1;

    /**
     * Shows the recording's first step, paused.
     *
     * @param recording the recording, read as far as it could be
     * @param model     the window's model
     */
    public ReplayPlayer(Recording recording, ViewModel model) {
        this.steps = recording.snapshots();
        this.model = model;
        this.timer = new Timer(1000, e -> tick());
        model.source("replay of " + recording.file().getFileName());
        if (steps.isEmpty()) {
            model.world(recording.world());
        } else {
            seek(0);
        }
        setSpeed(1);
    }

    /** @param observer called whenever the position, speed or playing state changes */
    public void observe(Runnable observer) {
        observers.add(observer);
    }

    private void changed() {
        for (Runnable r : observers) {
            r.run();
        }
    }

    /**
     * Shows one step, rebuilding the trails up to it.
     *
     * @param target the index of the step, clamped to the recording
     */
    public void seek(int target) {
        if (steps.isEmpty()) {
            return;
        }
        int i = Math.max(0, Math.min(steps.size() - 1, target));
        WorldDescription world = steps.get(i).world();
        if (model.world() != world) {
            model.world(world);
        }
        int start = i;
        while (start > 0 && steps.get(start - 1).world() == world) {
            start--;
        }
        List<Snapshot> history = new ArrayList<>(i - start + 1);
        for (int k = start; k <= i; k++) {
            history.add(steps.get(k).snapshot());
        }
        index = i;
        model.jump(history);
        changed();
    }

    /**
     * Moves some steps forward (extending the trails) or back.
     *
     * @param delta steps to move; negative moves back
     */
    public void step(int delta) {
        int target = Math.max(0, Math.min(steps.size() - 1, index + delta));
        if (delta <= 0 || target == index) {
            if (target != index) {
                seek(target);
            }
            return;
        }
        List<Snapshot> next = new ArrayList<>();
        for (int k = index + 1; k <= target; k++) {
            if (steps.get(k).world() != model.world()) {
                seek(target);
                return;
            }
            next.add(steps.get(k).snapshot());
        }
        index = target;
        model.snapshots(next);
        changed();
    }

    /** Starts playing from the current step; from the start if at the end. */
    public void play() {
        if (steps.isEmpty()) {
            return;
        }
        if (index >= steps.size() - 1) {
            seek(0);
        }
        timer.start();
        changed();
    }

    /** Stops playing, keeping the current step. */
    public void pause() {
        timer.stop();
        changed();
    }

    /** @return whether it is playing */
    public boolean playing() {
        return timer.isRunning();
    }

    /** One tick of the timer: the next steps, and a pause at the end. */
    void tick() {
        step(stepsPerTick);
        if (index >= steps.size() - 1) {
            pause();
        }
    }

    /**
     * @param multiple the speed as a multiple of real time, greater than 0
     * @throws IllegalArgumentException if it is not
     */
    public void setSpeed(double multiple) {
        if (!(multiple > 0) || Double.isInfinite(multiple)) {
            throw new IllegalArgumentException(multiple + " was supplied for speed: it must be greater than 0");
        }
        speed = multiple;
        int stepMs = steps.isEmpty() ? 100 : Math.max(1, steps.get(0).world().stepMs());
        double perStep = stepMs / speed;
        stepsPerTick = perStep >= MIN_TICK_MS ? 1 : (int) Math.ceil(MIN_TICK_MS / perStep);
        int delay = (int) Math.max(1, Math.round(stepsPerTick * perStep));
        timer.setDelay(delay);
        timer.setInitialDelay(delay);
        changed();
    }

    /** @return the speed, a multiple of real time */
    public double speed() {
        return speed;
    }

    /** @return how many steps a timer tick moves on */
    public int stepsPerTick() {
        return stepsPerTick;
    }

    /** @return the index of the step shown, or -1 if the recording has none */
    public int index() {
        return index;
    }

    /** @return how many steps the recording holds */
    public int size() {
        return steps.size();
    }
}
