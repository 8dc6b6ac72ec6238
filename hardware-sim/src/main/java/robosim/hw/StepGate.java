package robosim.hw;

import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import java.util.function.LongPredicate;

/**
 * Where a robot's code and its {@link HardwareSimulator} hand simulated time to each other. The
 * robot code's threads (its participants) run between steps and then yield: they wait for a
 * condition on simulated time ({@link #yieldUntil}, then {@link #awaitWake}). The hardware simulator publishes each new step
 * ({@link #advance}), which wakes the participants whose condition now holds. Once every
 * participant has yielded again, the step's requests are sent, exactly once, by whichever thread
 * saw that moment: the last participant to yield, or the hardware thread itself when nobody woke.
 * The gate says which by its answers ({@link #yieldUntil}, {@link #leave}, {@link #advance} and
 * {@link #claimIfYielded} return true to exactly one caller per step); it sends nothing itself. So
 * what a robot requests for a step never depends on thread timing, and no extra thread wakes just
 * to send.
 */
public final class StepGate {
    private final Set<Thread> participants = new LinkedHashSet<>();
    private final Map<Thread, LongPredicate> waiting = new LinkedHashMap<>();
    private long timeMs;
    private long step;
    private volatile long unsentSince = -1;
    private Runnable pending;
    private long pendingStep;
    private long pendingTime;
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
     * @return true if the others have all yielded, so the caller must send the step's requests now
     */
    public synchronized boolean leave(Thread thread) {
        participants.remove(thread);
        waiting.remove(thread);
        notifyAll();
        return claim();
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

    /** @return the robot-code threads still alive */
    public synchronized int participantCount() {
        participants.removeIf(t -> !t.isAlive());
        return participants.size();
    }

    /**
     * Yields the calling thread until {@code wakeWhen} holds for the simulated time (or the
     * connection ends); it then waits in {@link #awaitWake}. The calling thread becomes a
     * participant if it was not one.
     *
     * @param wakeWhen a condition on simulated time in ms, checked as each step arrives
     * @return true if it is the last participant to yield for the open step, so the caller must
     *         send the step's requests (before it waits)
     */
    public synchronized boolean yieldUntil(LongPredicate wakeWhen) {
        Thread me = Thread.currentThread();
        participants.add(me);
        waiting.put(me, wakeWhen);
        return claim();
    }

    /**
     * Ends a yield of the calling thread that it never waits out: its code runs on once it is back
     * from waiting on another robot ({@link HardwareSimulator#park}).
     */
    public synchronized void stopWaiting() {
        waiting.remove(Thread.currentThread());
    }

    /**
     * Waits until a step satisfies the condition the calling thread yielded with
     * ({@link #yieldUntil}), or the connection ends; returns at once if that has already happened.
     *
     * @throws InterruptedException if interrupted while waiting
     */
    public synchronized void awaitWake() throws InterruptedException {
        Thread me = Thread.currentThread();
        try {
            while (!closed && waiting.containsKey(me)) {
                wait();
            }
        } finally {
            waiting.remove(me);
        }
    }

    /**
     * Publishes a new step. If every participant has yielded, runs {@code update} (which installs
     * the new state) and wakes the participants whose condition now holds, atomically. If the
     * robot's code is still running (the first step can arrive while it runs after connecting), the
     * step is held and installed by the last participant to yield, so the state never changes under
     * running code; the caller goes back to listening meanwhile.
     *
     * @param newStep the step the state belongs to
     * @param newTime its simulated time, ms
     * @param update  installs the new state
     * @return true if nobody woke, so the caller must send the step's requests now
     */
    public synchronized boolean advance(long newStep, long newTime, Runnable update) {
        unsentSince = System.nanoTime();
        if (!allYielded()) {
            pending = update;
            pendingStep = newStep;
            pendingTime = newTime;
            return false;
        }
        install(newStep, newTime, update);
        return claim();
    }

    private void install(long newStep, long newTime, Runnable update) {
        update.run();
        step = newStep;
        timeMs = newTime;
        waiting.entrySet().removeIf(e -> e.getValue().test(newTime));
        notifyAll();
    }

    /**
     * Claims the open step's sending if every participant still alive has yielded: for a watchdog
     * that looks after participants which ended without yielding.
     *
     * @return true if the caller must send the step's requests now
     */
    public synchronized boolean claimIfYielded() {
        return claim();
    }

    /**
     * Read without the gate's lock, so that a watchdog looking after many robots can pass over the
     * ones with nothing to look at cheaply.
     *
     * @return nanoseconds (of {@link System#nanoTime}) since the open step's state arrived and its
     *         requests are still unsent, or -1 if nothing is waiting to be sent
     */
    public long unsentNanos() {
        long since = unsentSince;
        return since < 0 ? -1 : System.nanoTime() - since;
    }

    private boolean claim() {
        if (closed || unsentSince < 0 || !allYielded()) {
            return false;
        }
        if (pending != null) {
            Runnable update = pending;
            pending = null;
            install(pendingStep, pendingTime, update);
            if (!allYielded()) {
                return false;
            }
        }
        unsentSince = -1;
        return true;
    }

    private boolean allYielded() {
        // every waiting thread is a live participant: when all participants wait, none has died
        if (waiting.size() == participants.size()) {
            return true;
        }
        participants.removeIf(t -> !t.isAlive());
        waiting.keySet().removeIf(t -> !t.isAlive());
        return waiting.keySet().containsAll(participants);
    }

    /**
     * Waits until the gate is closed.
     *
     * @throws InterruptedException if interrupted
     */
    public synchronized void awaitClosed() throws InterruptedException {
        while (!closed) {
            wait();
        }
    }

    /** Ends the gate: every waiting thread returns. */
    public synchronized void close() {
        closed = true;
        notifyAll();
    }
}
