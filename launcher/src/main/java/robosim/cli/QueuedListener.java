package robosim.cli;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;

/**
 * Hands a listener's calls, in order, to a thread of its own, so that slow drawing (PNG and GIF
 * frames) does not hold up the viewer reading the run: the Environment gives its viewers only a
 * moment after the last step to take what it has queued for them. The snapshots wait here, small,
 * until they are drawn; {@link #close} waits for the last of them.
 */
final class QueuedListener implements SnapshotListener {
    /** Calls held at most; past it the viewer waits. A snapshot is a few kB. */
    static final int MAX_QUEUED = 100_000;
    /** How long {@link #close} waits for the calls still queued, minutes. */
    static final long CLOSE_WAIT_MIN = 10;

    @FunctionalInterface
    private interface Call {
        void on(SnapshotListener target) throws IOException;
    }

    private static final Call CLOSE = SnapshotListener::close;

    private final BlockingQueue<Call> calls = new LinkedBlockingQueue<>(MAX_QUEUED);
    private final Thread worker;
    private volatile IOException failure;

    /**
     * @param name   the thread's name
     * @param target the listener called on that thread
     */
    QueuedListener(String name, SnapshotListener target) {
        worker = new Thread(() -> work(target), name);
        worker.setDaemon(true);
        worker.start();
    }

    private void work(SnapshotListener target) {
        while (true) {
            Call call;
            try {
                call = calls.take();
            } catch (InterruptedException e) {
                return;
            }
            // after a failure only the close still reaches the target, so that it lets go of its files
            if (failure == null || call == CLOSE) {
                try {
                    call.on(target);
                } catch (IOException e) {
                    failure = failure == null ? e : failure;
                } catch (RuntimeException | Error e) {
                    // an Error too (a font or native library a headless JDK lacks): it is reported, not lost
                    failure = failure == null ? new IOException(e.toString(), e) : failure;
                }
            }
            if (call == CLOSE) {
                return;
            }
        }
    }

    @Override
    public void world(WorldDescription world) throws IOException {
        enqueue(t -> t.world(world));
    }

    @Override
    public void snapshot(Snapshot snapshot) throws IOException {
        enqueue(t -> t.snapshot(snapshot));
    }

    @Override
    public void end(String reason) throws IOException {
        enqueue(t -> t.end(reason));
    }

    /** Waits for every queued call, then for the target's close; throws the first failure. */
    @Override
    public void close() throws IOException {
        try {
            calls.put(CLOSE);
            worker.join(TimeUnit.MINUTES.toMillis(CLOSE_WAIT_MIN));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted while " + worker.getName() + " finished");
        }
        if (worker.isAlive()) {
            throw new IOException(worker.getName() + " had not finished " + CLOSE_WAIT_MIN + " minutes after the run");
        }
        if (failure != null) {
            throw failure;
        }
    }

    private void enqueue(Call call) throws IOException {
        if (failure != null) {
            throw failure;
        }
        try {
            calls.put(call);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted while queueing for " + worker.getName());
        }
    }
}
