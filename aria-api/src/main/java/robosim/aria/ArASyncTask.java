package robosim.aria;

/**
 * ARIA's asynchronous task ({@code ArASyncTask}, ArASyncTask.h): a subclass gives {@link
 * #runThread(Object)}, and {@link #runAsync()} runs it in a new thread (or {@link #run()} in the
 * calling one). The body polls {@link #getRunning()} or {@link #getRunningWithLock()} and ends when
 * another thread calls {@link #stopRunning()}.
 */
public abstract class ArASyncTask extends ArThread {
    /** A task not yet started. */
    protected ArASyncTask() {
    }

    /**
     * The task's body, run in its thread.
     *
     * @param arg the argument given to {@link #runInThisThread(Object)}, null from {@link #runAsync()}
     * @return anything; ARIA ignores it
     */
    public abstract Object runThread(Object arg);

    /** Runs the task in the calling thread, as ARIA's {@code run()}. */
    public void run() {
        runInThisThread(null);
    }

    /** Runs the task in a new thread, as ARIA's {@code runAsync()}: {@link #create(boolean, boolean)}. */
    public void runAsync() {
        create(true, true);
    }

    /**
     * Starts the task's thread.
     *
     * @param joinable      whether {@link #join()} may wait for it
     * @param lowerPriority whether it runs at a lower priority than the program's thread
     * @return 0, or {@link #STATUS_FAILED} if it was already started
     */
    public int create(boolean joinable, boolean lowerPriority) {
        return create(() -> runThread(null), joinable, lowerPriority);
    }

    /**
     * Runs the task's body in the calling thread, with the running flag set, as ARIA's {@code
     * runInThisThread} (ArASyncTask.cpp) does.
     *
     * @param arg the body's argument
     * @return what the body returns
     */
    public Object runInThisThread(Object arg) {
        setRunning(true);
        ArLog.log(getLogLevel(), "Running %s", describe());
        return runThread(arg);
    }
}
