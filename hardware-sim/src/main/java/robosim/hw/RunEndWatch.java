package robosim.hw;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Follows the robots of a {@link RobotRuntime} from the moment it is opened: how many are still in
 * their run (connecting or connected), and how each of the others ended. It is for a launcher that
 * runs a robot program and reports its robots' ends ({@code robosim robot}); a program reads its own
 * robot's end with {@link AbstractRobot#getRunEnd()}.
 */
public final class RunEndWatch implements AutoCloseable {
    private final RunEndWatches watches;
    private final Set<HardwareSimulator> running = new HashSet<>();
    private final List<RunEnd> ends = new ArrayList<>();

    RunEndWatch(RunEndWatches watches) {
        this.watches = watches;
    }

    /**
     * @return a watch that follows, until closed, every robot of the default runtime (every robot
     *         given no runtime of its own) that begins to connect from now on, in this default
     *         runtime and in the fresh ones made after it closes
     */
    public static RunEndWatch open() {
        return RobotRuntime.defaultRuntime().runEndWatches().open();
    }

    /**
     * @param runtime the runtime whose robots to follow
     * @return a watch that follows every robot of {@code runtime} that begins to connect from now on, until closed
     */
    public static RunEndWatch open(RobotRuntime runtime) {
        return runtime.runEndWatches().open();
    }

    synchronized void add(HardwareSimulator hw) {
        running.add(hw);
        notifyAll();
    }

    synchronized void remove(HardwareSimulator hw, RunEnd end) {
        if (running.remove(hw)) {
            ends.add(end);
            notifyAll();
        }
    }

    /** @return the robots followed that are connecting or connected */
    public synchronized int running() {
        return running.size();
    }

    /**
     * A robot followed that has had no step yet: it is still connecting, or it is in the run and the
     * Environment has not begun it (it starts once every robot its world names has connected).
     *
     * @param robot       the robot's name
     * @param environment the Environment's host and port, {@code host:port}
     * @param welcomed    whether the Environment has welcomed the robot into its world
     * @param waitedNanos since the robot began to connect, ns
     * @param afterStep   once welcomed, the steps the run had run then: 0 when the run had not begun, more
     *                    for a robot that joined a run under way (which may be paused); -1 before
     */
    public record BeforeFirstStep(String robot, String environment, boolean welcomed, long waitedNanos,
                                  long afterStep) {
        /**
         * A robot that has had no step yet, welcomed before its run began (or not welcomed yet).
         *
         * @param robot       the robot's name
         * @param environment the Environment's host and port
         * @param welcomed    whether the Environment has welcomed it
         * @param waitedNanos since it began to connect, ns
         */
        public BeforeFirstStep(String robot, String environment, boolean welcomed, long waitedNanos) {
            this(robot, environment, welcomed, waitedNanos, welcomed ? 0 : -1);
        }
    }

    /** @return the robots followed that are connecting or connected and have had no step yet */
    public List<BeforeFirstStep> beforeFirstStep() {
        List<HardwareSimulator> robots;
        synchronized (this) {
            robots = new ArrayList<>(running);
        }
        List<BeforeFirstStep> waiting = new ArrayList<>();
        for (HardwareSimulator hw : robots) {
            BeforeFirstStep b = hw.beforeFirstStep();
            if (b != null) {
                waiting.add(b);
            }
        }
        return waiting;
    }

    /** @return how the robots followed ended, in the order they ended */
    public synchronized List<RunEnd> ends() {
        return List.copyOf(ends);
    }

    /**
     * Waits until no robot followed is connecting or connected.
     *
     * @param timeoutMs the longest wait, ms
     * @return whether none is
     * @throws InterruptedException if interrupted
     */
    public synchronized boolean awaitNoneRunning(long timeoutMs) throws InterruptedException {
        long deadline = System.nanoTime() + timeoutMs * 1_000_000L;
        while (!running.isEmpty()) {
            long left = (deadline - System.nanoTime()) / 1_000_000L;
            if (left <= 0) {
                return false;
            }
            wait(left);
        }
        return true;
    }

    /** Stops following robots. */
    @Override
    public void close() {
        watches.closed(this);
    }
}
