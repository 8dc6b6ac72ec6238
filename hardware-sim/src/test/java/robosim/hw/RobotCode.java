package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;

/**
 * The threads a test runs robot code on. Each must end within {@link FakeEnvironment#WAIT_MS} of
 * being joined; {@link #close} joins them all and reports the first failure of any.
 */
final class RobotCode implements AutoCloseable {
    /** A robot's code. */
    @FunctionalInterface
    interface Body {
        void run() throws Exception;
    }

    private final List<Thread> threads = new ArrayList<>();
    private final Queue<Throwable> failures = new ConcurrentLinkedQueue<>();

    /** Starts a daemon thread running {@code body}; what it throws fails the test at {@link #close}. */
    Thread start(String name, Body body) {
        Thread t = new Thread(() -> {
            try {
                body.run();
            } catch (Throwable e) {
                failures.add(e);
            }
        }, name);
        t.setDaemon(true);
        synchronized (threads) {
            threads.add(t);
        }
        t.start();
        return t;
    }

    /** Waits (bounded) for a thread to end. */
    static void join(Thread t) throws InterruptedException {
        t.join(FakeEnvironment.WAIT_MS);
        assertFalse(t.isAlive(), t.getName() + " is still running");
    }

    @Override
    public void close() throws InterruptedException {
        List<Thread> all;
        synchronized (threads) {
            all = List.copyOf(threads);
        }
        List<String> running = new ArrayList<>();
        for (Thread t : all) {
            t.join(FakeEnvironment.WAIT_MS);
            if (t.isAlive()) {
                running.add(t.getName());
                t.interrupt();
                t.join(FakeEnvironment.WAIT_MS);
            }
        }
        Throwable first = failures.peek();
        if (first != null) {
            throw new AssertionError("robot code failed: " + first, first);
        }
        if (!running.isEmpty()) {
            fail("robot code still running after the test: " + running);
        }
    }
}
