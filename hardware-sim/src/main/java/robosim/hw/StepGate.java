package robosim.hw;

import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import java.util.function.LongPredicate;

/**
 * Where a robot's code and its {@link HardwareSimulator} hand simulated time to each other. The
 * robot code's threads (its participants) run between steps and then yield: they wait for a
 * condition on simulated time ({@link #await}). The hardware simulator publishes each new step's
 * time ({@link #advance}), which wakes the participants whose condition now holds, and then waits
 * until every participant has yielded again ({@link #awaitYield}) before it sends the step's
 * requests. So what a robot requests for a step never depends on thread timing.
 */
public final class StepGate {
    private final Set<Thread> participants = new LinkedHashSet<>();
    private final Map<Thread, LongPredicate> waiting = new LinkedHashMap<>();
    private long timeMs;
    private long step;
    private boolean closed;

    /**
     * Makes a thread one whose yields the steps wait for.
     *
     * @param thread a thread of the robot's code
     */
    public synchronized void join(Thread thread) {
        participants.add(thread);
    }

    /**
     * Stops waiting for a thread's yields.
     *
     * @param thread a thread of the robot's code
     */
    public synchronized void leave(Thread thread) {
        participants.remove(thread);
        waiting.remove(thread);
        notifyAll();
    }

    /** @return simulated time of the latest state, ms */
    public synchronized long timeMs() {
        return timeMs;
    }

    /** @return the latest step whose state has arrived */
    public synchronized long step() {
        return step;
    }

    /** @return whether the connection has ended */
    public synchronized boolean isClosed() {
        return closed;
    }

    /**
     * Yields the calling thread until {@code wakeWhen} holds for the simulated time (or the
     * connection ends). The calling thread becomes a participant if it was not one.
     *
     * @param wakeWhen a condition on simulated time in ms, checked as each step arrives
     * @throws InterruptedException if interrupted while waiting
     */
    public synchronized void await(LongPredicate wakeWhen) throws InterruptedException {
        Thread me = Thread.currentThread();
        participants.add(me);
        waiting.put(me, wakeWhen);
        notifyAll();
        try {
            while (!closed && waiting.containsKey(me)) {
                wait();
            }
        } finally {
            waiting.remove(me);
        }
    }

    /**
     * Publishes a new step: runs {@code update} (which installs the new state) and wakes the
     * participants whose condition now holds, atomically.
     *
     * @param newStep the step the state belongs to
     * @param newTime its simulated time, ms
     * @param update  installs the new state
     */
    public synchronized void advance(long newStep, long newTime, Runnable update) {
        update.run();
        step = newStep;
        timeMs = newTime;
        waiting.entrySet().removeIf(e -> e.getValue().test(newTime));
        notifyAll();
    }

    /**
     * Waits until every participant has yielded (or has ended).
     *
     * @param timeoutMs the longest wait
     * @return the number of participants still alive, or -1 if the wait timed out
     * @throws InterruptedException if interrupted
     */
    public synchronized int awaitYield(long timeoutMs) throws InterruptedException {
        long deadline = System.currentTimeMillis() + timeoutMs;
        while (!closed) {
            participants.removeIf(t -> !t.isAlive());
            waiting.keySet().removeIf(t -> !t.isAlive());
            if (waiting.keySet().containsAll(participants)) {
                return participants.size();
            }
            long left = deadline - System.currentTimeMillis();
            if (left <= 0) {
                return -1;
            }
            // a participant that ends without yielding sends no notification: look again soon
            wait(Math.min(left, 20));
        }
        return participants.size();
    }

    /** Ends the gate: every waiting thread returns. */
    public synchronized void close() {
        closed = true;
        notifyAll();
    }
}
