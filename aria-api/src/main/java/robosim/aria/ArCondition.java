package robosim.aria;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * ARIA's condition ({@code ArCondition}, ArCondition.h): a thread waits on it until another thread
 * signals it. As in ARIA, a signal with no thread waiting is lost: the condition keeps no state of
 * its own, so a program checks its own data under its own {@link ArMutex}. Unlike a bare platform
 * condition, a waiter does not wake without a signal. ARIA's {@code wait()} is {@link #await()}
 * here, as {@code wait()} is every Java object's.
 */
public class ArCondition {
    /** A general failure. */
    public static final int STATUS_FAILED = 1;
    /** Threads still wait on the condition (not in Java; kept for ARIA's codes). */
    public static final int STATUS_FAILED_DESTROY = 2;
    /** The condition could not be made (not in Java; kept for ARIA's codes). */
    public static final int STATUS_FAILED_INIT = 3;
    /** {@link #timedWait(int)} ended without a signal. */
    public static final int STATUS_WAIT_TIMEDOUT = 4;
    /** The wait was interrupted (the thread's interrupt, ARIA's signal). */
    public static final int STATUS_WAIT_INTR = 5;
    /** The underlying mutex could not be made (not in Java; kept for ARIA's codes). */
    public static final int STATUS_MUTEX_FAILED_INIT = 6;
    /** The underlying mutex failed (not in Java; kept for ARIA's codes). */
    public static final int STATUS_MUTEX_FAILED = 7;

    private final ReentrantLock lock = new ReentrantLock();
    private final Condition signalled = lock.newCondition();
    /** Signals so far: a waiter wakes when it changes (broadcast) or it takes a pending wake (signal). */
    private long broadcasts;
    private int wakes;
    private int waiting;
    private volatile String logName = "";

    /**
     * Wakes one thread waiting, if any.
     *
     * @return 0
     */
    public int signal() {
        lock.lock();
        try {
            if (wakes < waiting) {
                wakes++;
                signalled.signal();
            }
            return 0;
        } finally {
            lock.unlock();
        }
    }

    /**
     * Wakes every thread waiting.
     *
     * @return 0
     */
    public int broadcast() {
        lock.lock();
        try {
            broadcasts++;
            signalled.signalAll();
            return 0;
        } finally {
            lock.unlock();
        }
    }

    /**
     * Waits until the condition is signalled: ARIA's {@code wait()}, which in Java is {@link Object}'s
     * own, so the port writes {@code await()}.
     *
     * @return 0, or {@link #STATUS_WAIT_INTR} if the thread was interrupted (its interrupt kept)
     */
    public int await() {
        return awaitFor(-1);
    }

    /**
     * Waits until the condition is signalled, or for at most {@code msecs}.
     *
     * @param msecs the longest wait, wall-clock ms
     * @return 0 if signalled, {@link #STATUS_WAIT_TIMEDOUT}, or {@link #STATUS_WAIT_INTR}
     */
    public int timedWait(int msecs) {
        return awaitFor(Math.max(0, msecs));
    }

    private int awaitFor(long msecs) {
        lock.lock();
        try {
            long generation = broadcasts;
            long left = msecs < 0 ? Long.MAX_VALUE : TimeUnit.MILLISECONDS.toNanos(msecs);
            waiting++;
            try {
                while (wakes == 0 && broadcasts == generation) {
                    if (left <= 0) {
                        return STATUS_WAIT_TIMEDOUT;
                    }
                    left = msecs < 0 ? awaitForever() : signalled.awaitNanos(left);
                }
                if (broadcasts == generation) {
                    wakes--;
                }
                return 0;
            } finally {
                waiting--;
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return STATUS_WAIT_INTR;
        } finally {
            lock.unlock();
        }
    }

    private long awaitForever() throws InterruptedException {
        signalled.await();
        return Long.MAX_VALUE;
    }

    /**
     * @param messageNumber one of the status codes
     * @return ARIA's words for it
     */
    public String getError(int messageNumber) {
        return switch (messageNumber) {
            case 0 -> "No error";
            case STATUS_FAILED -> "General failure";
            case STATUS_FAILED_DESTROY -> "Another thread is waiting on this condition so it can not be destroyed";
            case STATUS_FAILED_INIT -> "Failed to initialize thread. Requested action is impossible";
            case STATUS_WAIT_TIMEDOUT -> "The timedwait timed out before signaling";
            case STATUS_WAIT_INTR -> "The wait was interupted by a signal";
            case STATUS_MUTEX_FAILED_INIT -> "The underlying mutex failed to init";
            case STATUS_MUTEX_FAILED -> "The underlying mutex failed in some fashion";
            default -> "error unknown";
        };
    }

    /** @param logName the name the log lines give the condition */
    public void setLogName(String logName) {
        this.logName = logName == null ? "" : logName;
    }

    /** @return the name the log lines give the condition, {@code unnamed} if none was given */
    public String getLogName() {
        return logName.isEmpty() ? "unnamed" : logName;
    }
}
