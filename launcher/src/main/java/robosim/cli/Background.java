package robosim.cli;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executor;
import java.util.function.Supplier;

/**
 * Runs long tasks (an Environment's run, a robot program, a viewer) each on a daemon thread of its
 * own, for the commands and the end-to-end tests. Not on the common pool: with two cores its
 * parallelism is 1, and newer JDKs run every {@code supplyAsync} task there, so a second long task
 * would wait for the first forever.
 */
public final class Background {
    private Background() {
    }

    /**
     * @param name the threads' name
     * @return an executor that starts a daemon thread of that name per task
     */
    public static Executor thread(String name) {
        return task -> {
            Thread t = new Thread(task, name);
            t.setDaemon(true);
            t.start();
        };
    }

    /**
     * Runs a task on a daemon thread of its own.
     *
     * @param name the thread's name
     * @param task what it runs
     * @param <T>  what the task gives
     * @return completed by the task's result
     */
    public static <T> CompletableFuture<T> supply(String name, Supplier<T> task) {
        return CompletableFuture.supplyAsync(task, thread(name));
    }

    /**
     * Runs a task on a daemon thread of its own.
     *
     * @param name the thread's name
     * @param task what it runs
     * @return completed when the task ends
     */
    public static CompletableFuture<Void> run(String name, Runnable task) {
        return CompletableFuture.runAsync(task, thread(name));
    }
}
