package robosim.env.core;

import java.util.function.IntConsumer;

/**
 * How the simulation runs work that is independent per robot (reading every robot's sensors): a
 * loop over robot indexes that may run its bodies on several threads. The core owns no threads;
 * whoever drives it passes a parallel loop in (the Environment builds one on a pool of
 * {@code --threads} workers). Results do not depend on it: each body touches only its own robot's
 * state and reads the world, which does not change during the loop.
 */
@FunctionalInterface
public interface Parallel {
    /** One index after another on the calling thread. */
    Parallel SERIAL = (n, body) -> {
        for (int i = 0; i < n; i++) {
            body.accept(i);
        }
    };

    /**
     * Runs {@code body} once for each index from 0 to {@code n} − 1, in any order and on any
     * threads, and returns when all have run; an exception thrown by a body is thrown here.
     *
     * @param n    how many indexes
     * @param body what to run for each
     */
    void forEach(int n, IntConsumer body);
}
