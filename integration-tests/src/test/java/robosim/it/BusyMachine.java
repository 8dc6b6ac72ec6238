package robosim.it;

import java.util.ArrayList;
import java.util.List;

/**
 * Keeps the machine busy on purpose, as other work on a shared machine does: threads that spin
 * without pause (twice as many as the processors unless told), from construction until closed.
 * For tests that must pass on a busy machine every time, not only on an idle one.
 */
final class BusyMachine implements AutoCloseable {
    private final List<Thread> spinners = new ArrayList<>();
    private volatile boolean stop;
    /** Written by the spinners so that their loop is not optimised away. */
    volatile long sink;

    /** @return a machine kept busy by twice as many spinning threads as it has processors */
    static BusyMachine twiceTheCores() {
        return new BusyMachine(2 * Runtime.getRuntime().availableProcessors());
    }

    /**
     * @param threads how many threads spin
     * @throws IllegalArgumentException if threads is below 1
     */
    BusyMachine(int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException(threads + " was supplied for threads: at least 1 spins");
        }
        for (int i = 0; i < threads; i++) {
            Thread t = new Thread(this::spin, "busy-machine-" + i);
            t.setDaemon(true);
            spinners.add(t);
            t.start();
        }
    }

    private void spin() {
        long x = Thread.currentThread().getId();
        while (!stop) {
            for (int i = 0; i < 1_000_000; i++) {
                x = x * 6364136223846793005L + 1442695040888963407L;
            }
            sink = x;
        }
    }

    /** @return how many threads spin */
    int threads() {
        return spinners.size();
    }

    /** Stops the spinning threads and waits for them to end. */
    @Override
    public void close() throws InterruptedException {
        stop = true;
        for (Thread t : spinners) {
            t.join(10_000);
        }
    }
}
