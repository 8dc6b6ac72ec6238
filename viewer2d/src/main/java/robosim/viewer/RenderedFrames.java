package robosim.viewer;

import java.io.IOException;
import robosim.protocol.ViewerFrame;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.FrameListener;

/**
 * Follows a run and hands images of it to a {@link FrameSink}: the frames whose step is a
 * multiple of {@code every}, and always the last one, so that the final state is kept. A reloaded
 * world draws the old world's last frame before it replaces the world. Used alike by the live
 * viewer and the replay, so their images agree.
 */
public final class RenderedFrames implements FrameListener {
    private final FramePainter painter;
    private final FrameSink sink;
    private final int every;
    private final Trails trails;
    private WorldDescription world;
    private ViewerFrame last;
    private boolean lastWritten = true;
    private long written;

    /**
     * @param painter draws each frame
     * @param sink    takes the images
     * @param every   draw frames whose step is a multiple of this, at least 1
     * @param trails  whether to keep the robots' paths and hand them to the painter
     */
    public RenderedFrames(FramePainter painter, FrameSink sink, int every, boolean trails) {
        if (painter == null || sink == null) {
            throw new IllegalArgumentException("null was supplied for " + (painter == null ? "painter" : "sink")
                    + ": it is required");
        }
        if (every < 1) {
            throw new IllegalArgumentException(every + " was supplied for every: every must be at least 1");
        }
        this.painter = painter;
        this.sink = sink;
        this.every = every;
        this.trails = trails ? new Trails() : null;
    }

    @Override
    public void world(WorldDescription newWorld) throws IOException {
        flush();
        last = null;
        if (trails != null) {
            trails.clear();
        }
        world = newWorld;
    }

    @Override
    public void frame(ViewerFrame frame) throws IOException {
        skip(frame);
        lastWritten = false;
        if (frame.step() % every == 0) {
            write(frame);
        }
    }

    /**
     * Takes a frame without drawing it (one before a replay's first step): its robots still
     * extend their trails.
     *
     * @param frame the frame
     */
    public void skip(ViewerFrame frame) {
        if (trails != null) {
            trails.add(frame);
        }
        last = frame;
        lastWritten = true;
    }

    @Override
    public void end(String reason) throws IOException {
        flush();
    }

    /** Draws the last frame if it has not been drawn. */
    @Override
    public void close() throws IOException {
        flush();
    }

    private void flush() throws IOException {
        if (last != null && !lastWritten) {
            write(last);
        }
    }

    private void write(ViewerFrame frame) throws IOException {
        if (world == null) {
            throw new IllegalStateException("frame of step " + frame.step() + " before any world");
        }
        lastWritten = true;
        sink.accept(frame.step(), painter.paint(world, frame, trails));
        written++;
    }

    /** @return how many images have been handed to the sink */
    public long written() {
        return written;
    }
}
