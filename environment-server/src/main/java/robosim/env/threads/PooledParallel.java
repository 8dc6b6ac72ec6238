package robosim.env.threads;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.IntConsumer;
import robosim.env.core.Parallel;

/**
 * The simulation's parallel loop on a fixed pool: the calling thread and {@code threads − 1}
 * workers (daemons named {@code env-worker-N}) take chunks of the indexes, a few chunks per
 * thread, until none is left; the call returns when every chunk has run. A chunk holds at least
 * {@value #MIN_CHUNK} indexes (waking a worker costs about as much as reading a few robots'
 * sensors), so a short loop runs on the caller alone. With one thread there is no pool and the
 * loop always runs on the caller. Close it to stop the workers.
 *
 * <p>Each index runs exactly once; which thread runs it does not matter to the simulation, whose
 * loop bodies touch only their own robot. The workers' writes are visible to the caller when the
 * call returns.
 */
public final class PooledParallel implements Parallel, AutoCloseable {
    /** Chunks per thread: enough for an even share when robots cost unequally (a laser costs more). */
    private static final int CHUNKS_PER_THREAD = 4;
    /** The fewest indexes in a chunk. */
    public static final int MIN_CHUNK = 16;
    /** How long the caller spins for the last chunks before it sleeps, ns. */
    private static final long SPIN_NANOS = 200_000;

    private final int threads;
    private final ExecutorService workers;

    /**
     * @param threads how many threads run the loop, the caller included, at least 1
     * @throws IllegalArgumentException if {@code threads} is below 1
     */
    public PooledParallel(int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException(threads + " was supplied for threads: it must be at least 1");
        }
        this.threads = threads;
        AtomicInteger made = new AtomicInteger();
        this.workers = threads == 1 ? null : Executors.newFixedThreadPool(threads - 1, r -> {
            Thread t = new Thread(r, "env-worker-" + made.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
    }

    @Override
    public void forEach(int n, IntConsumer body) {
        forEach(n, MIN_CHUNK, body);
    }

    /**
     * {@link #forEach(int, IntConsumer)} for bodies that each cost much more than reading one
     * robot's sensors (encoding a frame of many robots' states): chunks may be smaller.
     *
     * @param n        how many indexes
     * @param minChunk the fewest indexes in a chunk, at least 1
     * @param body     what to run for each
     */
    public void forEach(int n, int minChunk, IntConsumer body) {
        int chunks = Math.min(n / Math.max(1, minChunk), threads * CHUNKS_PER_THREAD);
        if (workers == null || chunks < 2) {
            Parallel.SERIAL.forEach(n, body);
            return;
        }
        Loop loop = new Loop(n, chunks, body);
        for (int i = 1; i < threads; i++) {
            try {
                workers.execute(loop::work);
            } catch (RejectedExecutionException e) {
                // closed meanwhile: the caller takes every chunk left
                break;
            }
        }
        loop.work();
        loop.await();
    }

    /** One call's chunks: taken in turn by whichever thread asks next. */
    private static final class Loop {
        private final int n;
        private final int chunks;
        private final IntConsumer body;
        private final AtomicInteger next = new AtomicInteger();
        private final CountDownLatch done;
        private final AtomicReference<Throwable> failure = new AtomicReference<>();

        Loop(int n, int chunks, IntConsumer body) {
            this.n = n;
            this.chunks = chunks;
            this.body = body;
            this.done = new CountDownLatch(chunks);
        }

        void work() {
            for (int c = next.getAndIncrement(); c < chunks; c = next.getAndIncrement()) {
                try {
                    int end = (int) ((long) (c + 1) * n / chunks);
                    for (int i = (int) ((long) c * n / chunks); i < end; i++) {
                        body.accept(i);
                    }
                } catch (Throwable t) {
                    failure.compareAndSet(null, t);
                } finally {
                    done.countDown();
                }
            }
        }

        /**
         * Waits for every chunk, then throws what a body threw, if any did. The caller spins a
         * little before it sleeps: the last chunks are usually a moment from done, and waking a
         * sleeping thread can take longer than that.
         */
        void await() {
            long spinUntil = System.nanoTime() + SPIN_NANOS;
            while (done.getCount() > 0 && System.nanoTime() < spinUntil) {
                Thread.onSpinWait();
            }
            boolean interrupted = false;
            while (true) {
                try {
                    done.await();
                    break;
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
            Throwable t = failure.get();
            if (t instanceof RuntimeException e) {
                throw e;
            }
            if (t instanceof Error e) {
                throw e;
            }
            if (t != null) {
                throw new IllegalStateException(t);
            }
        }
    }

    /** Stops the workers; a loop after that runs on the caller alone. */
    @Override
    public void close() {
        if (workers != null) {
            workers.shutdown();
        }
    }
}
