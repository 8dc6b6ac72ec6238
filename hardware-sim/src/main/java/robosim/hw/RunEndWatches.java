package robosim.hw;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The open {@link RunEndWatch}es that follow the robots of a runtime: a runtime made for a program
 * has its own; the default runtimes, one after another, share one, so that a watch opened on the
 * default runtime follows the robots of the fresh ones too.
 */
final class RunEndWatches {
    private final Set<RunEndWatch> open = ConcurrentHashMap.newKeySet();

    /** @return a watch that follows every robot that begins to connect from now on, until closed */
    RunEndWatch open() {
        RunEndWatch w = new RunEndWatch(this);
        open.add(w);
        return w;
    }

    /** A robot began to connect. */
    void joining(HardwareSimulator hw) {
        for (RunEndWatch w : open) {
            w.add(hw);
        }
    }

    /** A robot's part in the run ended; called once per robot. */
    void ended(HardwareSimulator hw, RunEnd end) {
        for (RunEndWatch w : open) {
            w.remove(hw, end);
        }
    }

    /** A watch stopped following robots. */
    void closed(RunEndWatch w) {
        open.remove(w);
    }
}
