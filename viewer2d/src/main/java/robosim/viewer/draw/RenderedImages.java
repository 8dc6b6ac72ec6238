package robosim.viewer.draw;

import java.io.IOException;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;

/**
 * Follows a run and hands images of it to a {@link ImageSink}: the snapshots whose step is a
 * multiple of {@code every}, and always the last one, so that the final state is kept. A reloaded
 * world draws the old world's last snapshot before it replaces the world. The robots' drawings are
 * folded forward from snapshot to snapshot, so each image shows them all, and so are the robots that
 * have gone ({@link Departures}), so each image draws them as gone. Used alike by the live
 * viewer and the replay, so their images agree.
 */
public final class RenderedImages implements SnapshotListener {
    private final SnapshotPainter painter;
    private final ImageSink sink;
    private final int every;
    private final Trails trails;
    private final Drawings drawings = new Drawings();
    private final Departures departures = new Departures();
    private WorldDescription world;
    private Snapshot last;
    private boolean lastWritten = true;
    private long written;

    /**
     * @param painter draws each snapshot
     * @param sink    takes the images
     * @param every   draw snapshots whose step is a multiple of this, at least 1
     * @param trails  whether to keep the robots' paths and hand them to the painter
     */
    public RenderedImages(SnapshotPainter painter, ImageSink sink, int every, boolean trails) {
        if (painter == null || sink == null) {
            throw new IllegalArgumentException("null was supplied for " + (painter == null ? "painter" : "sink")
                    + ": it is required");
        }
        requireEvery(every);
        this.painter = painter;
        this.sink = sink;
        this.every = every;
        this.trails = trails ? new Trails() : null;
    }

    /**
     * Images of the flat 2D view, without trails: what a plain PNG-writing viewer draws.
     *
     * @param sink   takes the images
     * @param render image width and what to show
     * @param every  draw snapshots whose step is a multiple of this, at least 1
     * @return the listener
     */
    public static RenderedImages flat(ImageSink sink, RenderOptions render, int every) {
        return new RenderedImages(SnapshotPainter.flat(new WorldRenderer(), render), sink, every, false);
    }

    /**
     * The rule for {@code every}, for callers that check it before building anything.
     *
     * @param every draw snapshots whose step is a multiple of this
     * @throws IllegalArgumentException if it is below 1
     */
    public static void requireEvery(int every) {
        if (every < 1) {
            throw new IllegalArgumentException(every + " was supplied for every: every must be at least 1");
        }
    }

    @Override
    public void world(WorldDescription newWorld) throws IOException {
        try {
            painter.checkDrawable(newWorld);
        } catch (IllegalArgumentException e) {
            throw new IOException("the world cannot be drawn: " + e.getMessage(), e);
        }
        flush();
        last = null;
        if (trails != null) {
            trails.clear();
        }
        drawings.clear();
        departures.clear();
        world = newWorld;
    }

    @Override
    public void snapshot(Snapshot snapshot) throws IOException {
        skip(snapshot);
        lastWritten = false;
        if (snapshot.step() % every == 0) {
            write(last);
        }
    }

    /**
     * Takes a snapshot without drawing it (one before a replay's first step): its robots still
     * extend their trails, and its drawings are kept.
     *
     * @param snapshot the snapshot
     */
    public void skip(Snapshot snapshot) {
        if (trails != null) {
            trails.add(snapshot);
        }
        drawings.add(snapshot);
        departures.add(snapshot);
        last = departures.over(drawings.over(snapshot));
        lastWritten = true;
    }

    @Override
    public void end(String reason) throws IOException {
        flush();
    }

    /** Draws the last snapshot if it has not been drawn. */
    @Override
    public void close() throws IOException {
        flush();
    }

    private void flush() throws IOException {
        if (last != null && !lastWritten) {
            write(last);
        }
    }

    private void write(Snapshot snapshot) throws IOException {
        if (world == null) {
            throw new IllegalStateException("snapshot of step " + snapshot.step() + " before any world");
        }
        lastWritten = true;
        sink.accept(snapshot.step(), painter.paint(world, snapshot, trails));
        written++;
    }

    /** @return how many images have been handed to the sink */
    public long written() {
        return written;
    }
}
