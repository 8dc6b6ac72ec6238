package robosim.aria;

import java.util.concurrent.locks.ReentrantLock;

/**
 * ARIA's mutex ({@code ArMutex}, ArMutex.h): a lock that threads share to keep data safe, with ARIA's
 * status codes instead of exceptions. Recursive by default, as ARIA's: the thread that holds it may
 * lock it again, and unlocks it as often.
 */
public class ArMutex {
    /** The platform's mutex could not be made (not in Java; kept for ARIA's codes). */
    public static final int STATUS_FAILED_INIT = 1;
    /** A general failure: unlocking a mutex the thread does not hold. */
    public static final int STATUS_FAILED = 2;
    /** {@link #tryLock()} found the mutex held by another thread. */
    public static final int STATUS_ALREADY_LOCKED = 3;

    private final ReentrantLock lock = new ReentrantLock();
    private final boolean recursive;
    private volatile String logName = "(unnamed)";
    private volatile boolean log;

    /** A recursive mutex, as ARIA's default. */
    public ArMutex() {
        this(true);
    }

    /**
     * @param recursive whether the thread that holds it may lock it again (ARIA's default); if not,
     *                  a second lock by the holder is refused with {@link #STATUS_ALREADY_LOCKED}
     *                  instead of deadlocking
     */
    public ArMutex(boolean recursive) {
        this.recursive = recursive;
    }

    /**
     * Locks the mutex, waiting for it if another thread holds it.
     *
     * @return 0, or {@link #STATUS_ALREADY_LOCKED} when a non-recursive mutex is locked again by its holder
     */
    public int lock() {
        if (!recursive && lock.isHeldByCurrentThread()) {
            ArLog.log(ArLog.Terse, "ArMutex::lock: %s: already locked by this thread", logName);
            return STATUS_ALREADY_LOCKED;
        }
        if (log) {
            ArLog.log(ArLog.Terse, "Locking %s", logName);
        }
        lock.lock();
        return 0;
    }

    /**
     * Locks the mutex if no other thread holds it, without waiting.
     *
     * @return 0 if locked, else {@link #STATUS_ALREADY_LOCKED}
     */
    public int tryLock() {
        if (!recursive && lock.isHeldByCurrentThread()) {
            return STATUS_ALREADY_LOCKED;
        }
        return lock.tryLock() ? 0 : STATUS_ALREADY_LOCKED;
    }

    /**
     * Unlocks the mutex once.
     *
     * @return 0, or {@link #STATUS_FAILED} (logged) if the calling thread does not hold it
     */
    public int unlock() {
        if (!lock.isHeldByCurrentThread()) {
            ArLog.log(ArLog.Terse, "ArMutex::unlock: %s: not locked by this thread", logName);
            return STATUS_FAILED;
        }
        if (log) {
            ArLog.log(ArLog.Terse, "Unlocking %s", logName);
        }
        lock.unlock();
        return 0;
    }

    /**
     * @param messageNumber one of the status codes
     * @return ARIA's words for it
     */
    public String getError(int messageNumber) {
        return switch (messageNumber) {
            case 0 -> "No error";
            case STATUS_FAILED_INIT -> "Failed to initialize";
            case STATUS_FAILED -> "General failure";
            case STATUS_ALREADY_LOCKED -> "Mutex already locked";
            default -> "error unknown";
        };
    }

    /** @param log whether each lock and unlock is logged */
    public void setLog(boolean log) {
        this.log = log;
    }

    /** @param logName the name the log lines give the mutex */
    public void setLogName(String logName) {
        this.logName = logName == null ? "(unnamed)" : logName;
    }

    /**
     * ARIA's {@code setLogNameVar}: the name from a format.
     *
     * @param format a {@link String#format} format
     * @param args   its arguments
     */
    public void setLogNameVar(String format, Object... args) {
        setLogName(String.format(java.util.Locale.ROOT, format, args));
    }

    /** @return the name the log lines give the mutex */
    public String getLogName() {
        return logName;
    }
}
