package robosim.cli;

import java.io.PrintWriter;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;

/**
 * Shows how far a viewer or a replay has come, on a {@link StatusLine}: the step, the frames seen
 * and the images written. On a terminal the line is redrawn at most four times a second; anywhere
 * else a plain line comes every {@link RunProgressLine#PLAIN_EVERY_S} s.
 */
final class FrameProgress implements SnapshotListener {
    private static final long TERMINAL_EVERY_NANOS = TimeUnit.MILLISECONDS.toNanos(RunProgressLine.INTERVAL_MS);

    private final StatusLine line;
    private final LongSupplier clock;
    private final String what;
    private final LongSupplier images;
    private final long every;
    private final long started;
    private long last;
    private long frames;

    /**
     * @param line   where to show it
     * @param clock  the time, ns
     * @param what   what is going on, such as {@code viewer} or {@code replay}
     * @param images the images written so far
     */
    FrameProgress(StatusLine line, LongSupplier clock, String what, LongSupplier images) {
        this.line = line;
        this.clock = clock;
        this.what = what;
        this.images = images;
        this.every = line.isTerminal() ? TERMINAL_EVERY_NANOS : TimeUnit.SECONDS.toNanos(RunProgressLine.PLAIN_EVERY_S);
        this.started = clock.getAsLong();
        this.last = started;
    }

    /**
     * @param err    the command's standard error
     * @param quiet  whether to show nothing
     * @param what   what is going on, such as {@code viewer} or {@code replay}
     * @param images the images written so far
     * @return the progress, or null if quiet
     */
    static FrameProgress on(PrintWriter err, boolean quiet, String what, LongSupplier images) {
        return quiet ? null : new FrameProgress(StatusLine.on(err), System::nanoTime, what, images);
    }

    @Override
    public void world(WorldDescription world) {
        // the snapshots tell the progress
    }

    @Override
    public void snapshot(Snapshot snapshot) {
        step(snapshot.step());
    }

    /**
     * One more frame.
     *
     * @param step its step
     */
    void step(long step) {
        frames++;
        long now = clock.getAsLong();
        if (now - last < every) {
            return;
        }
        last = now;
        long written = images.getAsLong();
        line.show(what + ": step " + step + ", " + frames + " frames" + (written > 0 ? ", " + written + " images written" : "")
                + ", " + RunProgressLine.duration(now - started) + " elapsed");
    }

    /** Clears a terminal's line. */
    @Override
    public void close() {
        line.close();
    }
}
