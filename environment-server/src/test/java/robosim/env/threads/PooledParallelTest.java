package robosim.env.threads;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicIntegerArray;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.env.net.ServerOptions;

/** The pool's loop runs every index once, on any number of threads, and passes failures on. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class PooledParallelTest {
    @Test
    void everyIndexRunsExactlyOnce() {
        for (int threads : new int[] {1, 2, 3, 8}) {
            try (PooledParallel p = new PooledParallel(threads)) {
                for (int n : new int[] {0, 1, 2, 3, 7, 31, 32, 33, 1000}) {
                    for (int round = 0; round < 20; round++) {
                        AtomicIntegerArray runs = new AtomicIntegerArray(n);
                        p.forEach(n, runs::incrementAndGet);
                        for (int i = 0; i < n; i++) {
                            assertEquals(1, runs.get(i), "index " + i + " of " + n + " on " + threads + " threads");
                        }
                        AtomicIntegerArray single = new AtomicIntegerArray(n);
                        p.forEach(n, 1, single::incrementAndGet);
                        for (int i = 0; i < n; i++) {
                            assertEquals(1, single.get(i), "index " + i + " of " + n + " in chunks of one or more");
                        }
                    }
                }
            }
        }
    }

    @Test
    void aFailureInTheLoopIsThrownToTheCaller() {
        try (PooledParallel p = new PooledParallel(2)) {
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> p.forEach(100, i -> {
                if (i == 77) {
                    throw new IllegalStateException("index 77");
                }
            }));
            assertEquals("index 77", e.getMessage());
            // and the pool goes on working
            AtomicIntegerArray runs = new AtomicIntegerArray(10);
            p.forEach(10, runs::incrementAndGet);
            assertEquals(1, runs.get(9));
        }
    }

    @Test
    void aClosedPoolRunsTheLoopOnTheCaller() {
        PooledParallel p = new PooledParallel(3);
        p.close();
        AtomicIntegerArray runs = new AtomicIntegerArray(500);
        p.forEach(500, runs::incrementAndGet);
        for (int i = 0; i < 500; i++) {
            assertEquals(1, runs.get(i), "index " + i);
        }
    }

    @Test
    void noThreadsIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new PooledParallel(0));
        assertEquals("0 was supplied for threads: it must be at least 1", e.getMessage());
        IllegalArgumentException o = assertThrows(IllegalArgumentException.class,
                () -> ServerOptions.loopback().withThreads(0));
        assertEquals("0 was supplied for threads: it must be at least 1", o.getMessage());
    }
}
