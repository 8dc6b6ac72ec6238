package robosim.aria;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * ARIA's thread ({@code ArThread}, ArThread.h): runs a function in a new thread, with a running flag
 * the function polls ({@link #getRunning()}, {@link #stopRunning()}) and ARIA's status codes. The
 * threads are daemons, as an ARIA program ends when its {@code main} returns whatever they do. A
 * thread a robot's program starts belongs to that robot's code, so its {@link ArUtil#sleep} is in the
 * robot's simulated time.
 */
public class ArThread {
    /** The thread could not be made. */
    public static final int STATUS_FAILED = 1;
    /** Not enough resources for a thread. */
    public static final int STATUS_NORESOURCE = 2;
    /** The thread can no longer be found: it was never started. */
    public static final int STATUS_NO_SUCH_THREAD = 3;
    /** The thread is detached, or not joinable. */
    public static final int STATUS_INVALID = 4;
    /** A thread cannot join itself. */
    public static final int STATUS_JOIN_SELF = 5;
    /** The thread is already detached. */
    public static final int STATUS_ALREADY_DETATCHED = 6;

    private static final Map<Thread, ArThread> THREADS = new ConcurrentHashMap<>();
    private static volatile ArLog.LogLevel logLevel = ArLog.Verbose;

    private final ArMutex mutex = new ArMutex();
    private volatile Runnable func;
    private volatile boolean running;
    private volatile boolean joinable;
    private volatile boolean detached;
    private volatile String name = "";
    private volatile Thread thread;
    private volatile boolean started;
    private volatile boolean finished;

    /** A thread not yet created. */
    public ArThread() {
    }

    /**
     * A thread created at once, running {@code func}.
     *
     * @param func     what the thread runs
     * @param joinable whether {@link #join()} may wait for it
     */
    public ArThread(Runnable func, boolean joinable) {
        create(func, joinable, true);
    }

    /**
     * Starts a new thread running {@code func}, with the running flag set.
     *
     * @param func          what the thread runs
     * @param joinable      whether {@link #join()} may wait for it
     * @param lowerPriority whether it runs at a lower priority than the program's thread
     * @return 0, or {@link #STATUS_FAILED} if this thread was already created
     */
    public int create(Runnable func, boolean joinable, boolean lowerPriority) {
        if (thread != null) {
            ArLog.log(ArLog.Terse, "ArThread::create: %s: already created", describe());
            return STATUS_FAILED;
        }
        this.func = func;
        this.joinable = joinable;
        running = true;
        Thread t = new Thread(this::body, name.isEmpty() ? "ArThread" : name);
        t.setDaemon(true);
        if (lowerPriority) {
            t.setPriority(Math.max(Thread.MIN_PRIORITY, Thread.currentThread().getPriority() - 1));
        }
        thread = t;
        THREADS.put(t, this);
        t.start();
        return 0;
    }

    private void body() {
        threadStarted();
        try {
            func.run();
        } finally {
            threadFinished();
        }
    }

    /** Asks the thread to stop: clears the running flag it polls. */
    public void stopRunning() {
        running = false;
    }

    /** @param running the running flag */
    public void setRunning(boolean running) {
        this.running = running;
    }

    /** @return the running flag: whether the thread is to go on */
    public boolean getRunning() {
        return running;
    }

    /** @return the running flag, read under the thread's lock, as ARIA's */
    public boolean getRunningWithLock() {
        lock();
        try {
            return running;
        } finally {
            unlock();
        }
    }

    /**
     * Waits for the thread to end.
     *
     * @return 0, {@link #STATUS_JOIN_SELF} from the thread itself, {@link #STATUS_INVALID} if it is
     *     detached or not joinable, {@link #STATUS_NO_SUCH_THREAD} if it was never created, or
     *     {@link #STATUS_FAILED} if the wait was interrupted
     */
    public int join() {
        Thread t = thread;
        if (t == null) {
            return STATUS_NO_SUCH_THREAD;
        }
        if (t == Thread.currentThread()) {
            return STATUS_JOIN_SELF;
        }
        if (detached || !joinable) {
            return STATUS_INVALID;
        }
        try {
            t.join();
            return 0;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return STATUS_FAILED;
        }
    }

    /**
     * Detaches the thread: it may no longer be joined.
     *
     * @return 0, or {@link #STATUS_ALREADY_DETATCHED}
     */
    public int detach() {
        if (detached) {
            return STATUS_ALREADY_DETATCHED;
        }
        detached = true;
        joinable = false;
        return 0;
    }

    /** Stops the thread: clears its running flag and interrupts it (ARIA cancels it outright). */
    public void cancel() {
        running = false;
        Thread t = thread;
        if (t != null) {
            t.interrupt();
        }
    }

    /** @return whether {@link #join()} may wait for it */
    public boolean getJoinable() {
        return joinable;
    }

    /** @return the Java thread, or null before {@link #create} */
    public Thread getThread() {
        return thread;
    }

    /** @return the thread's name, empty if none was given */
    public String getThreadName() {
        return name;
    }

    /** @param name the thread's name, also its Java thread's */
    public void setThreadName(String name) {
        this.name = name == null ? "" : name;
        Thread t = thread;
        if (t != null && !this.name.isEmpty()) {
            t.setName(this.name);
        }
    }

    /** @return what the thread is doing, for {@link #logThreadInfo()}: ARIA's default, unknown */
    public String getThreadActivity() {
        return "Unknown";
    }

    /** Called first in the new thread; logs its start at {@link #getLogLevel()}. */
    public void threadStarted() {
        started = true;
        ArLog.log(logLevel, "%s started", describe());
    }

    /** Called last in the thread; as in ARIA, the running flag stays as it was. */
    public void threadFinished() {
        finished = true;
        Thread t = thread;
        if (t != null) {
            THREADS.remove(t);
        }
    }

    /** @return whether the thread has started */
    public boolean isThreadStarted() {
        return started;
    }

    /** @return whether the thread has finished */
    public boolean isThreadFinished() {
        return finished;
    }

    /** Logs the thread's name, Java id and activity. */
    public void logThreadInfo() {
        Thread t = thread;
        ArLog.log(ArLog.Terse, "Thread %s, id %s, activity %s", describe(), t == null ? "none" : t.getId(),
                getThreadActivity());
    }

    /** @return 0: locks the thread's own mutex */
    public int lock() {
        return mutex.lock();
    }

    /** @return 0, or {@link ArMutex#STATUS_ALREADY_LOCKED} */
    public int tryLock() {
        return mutex.tryLock();
    }

    /** @return 0: unlocks the thread's own mutex */
    public int unlock() {
        return mutex.unlock();
    }

    String describe() {
        return name.isEmpty() ? "anonymous thread" : name + " thread";
    }

    /** @return the ArThread the calling thread is, or null for a thread ARIA did not start */
    public static ArThread self() {
        return THREADS.get(Thread.currentThread());
    }

    /** @return the calling thread's ArThread name, or null for a thread ARIA did not start */
    public static String getThisThreadName() {
        ArThread self = self();
        return self == null ? null : self.getThreadName();
    }

    /** Asks every running ArThread to stop. */
    public static void stopAll() {
        THREADS.values().forEach(ArThread::stopRunning);
    }

    /** Cancels every running ArThread. */
    public static void cancelAll() {
        THREADS.values().forEach(ArThread::cancel);
    }

    /** Waits for every joinable running ArThread but the caller to end. */
    public static void joinAll() {
        List<ArThread> all = new ArrayList<>(THREADS.values());
        for (ArThread t : all) {
            if (t.getThread() != Thread.currentThread()) {
                t.join();
            }
        }
    }

    /** @return the number of ArThreads running */
    public static int numThreads() {
        return THREADS.size();
    }

    /** Gives up the processor to other threads for a moment. */
    public static void yieldProcessor() {
        Thread.yield();
    }

    /** @return the level of the threads' start lines */
    public static ArLog.LogLevel getLogLevel() {
        return logLevel;
    }

    /** @param level the level of the threads' start lines */
    public static void setLogLevel(ArLog.LogLevel level) {
        logLevel = level;
    }
}
