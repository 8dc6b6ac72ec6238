package robosim.env.net;

import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinWorkerThread;
import java.util.concurrent.RecursiveAction;
import java.util.function.IntConsumer;
import robosim.env.core.Parallel;

/**
 * The simulation's parallel loop on a pool of worker threads: the indexes are cut into a few
 * chunks per thread, which the pool's threads share out while the caller waits. With one thread
 * there is no pool and the loop runs on the caller. Close it to stop the threads.
 */
public final class PooledParallel implements Parallel, AutoCloseable {
    /** Chunks per thread: enough for an even share when robots cost unequally (a laser costs more). */
    private static final int CHUNKS_PER_THREAD = 4;

    private final int threads;
    private final ForkJoinPool pool;

    /**
     * @param threads how many threads run the loop, at least 1
     * @throws IllegalArgumentException if {@code threads} is below 1
     */
    public PooledParallel(int threads) {
        ServerOptions.requireAtLeast("threads", threads, 1);
        this.threads = threads;
        this.pool = threads == 1 ? null : new ForkJoinPool(threads, p -> {
            ForkJoinWorkerThread t = ForkJoinPool.defaultForkJoinWorkerThreadFactory.newThread(p);
            t.setName("env-worker-" + t.getPoolIndex());
            t.setDaemon(true);
            return t;
        }, null, false);
    }

    /** @return how many threads run the loop */
    public int threads() {
        return threads;
    }

    @Override
    public void forEach(int n, IntConsumer body) {
        if (pool == null || n < 2) {
            Parallel.SERIAL.forEach(n, body);
            return;
        }
        int chunks = Math.min(n, threads * CHUNKS_PER_THREAD);
        pool.invoke(new Chunks(0, chunks, chunks, n, body));
    }

    /** Chunks {@code from} to {@code to} − 1 of {@code chunks} equal parts of the indexes 0 to n − 1. */
    private static final class Chunks extends RecursiveAction {
        private final int from;
        private final int to;
        private final int chunks;
        private final int n;
        private final transient IntConsumer body;

        Chunks(int from, int to, int chunks, int n, IntConsumer body) {
            this.from = from;
            this.to = to;
            this.chunks = chunks;
            this.n = n;
            this.body = body;
        }

        @Override
        protected void compute() {
            if (to - from > 1) {
                int mid = (from + to) >>> 1;
                invokeAll(new Chunks(from, mid, chunks, n, body), new Chunks(mid, to, chunks, n, body));
                return;
            }
            int end = (int) ((long) to * n / chunks);
            for (int i = (int) ((long) from * n / chunks); i < end; i++) {
                body.accept(i);
            }
        }
    }

    /** Stops the pool's threads; the loop must not be used after. */
    @Override
    public void close() {
        if (pool != null) {
            pool.shutdown();
        }
    }
}
