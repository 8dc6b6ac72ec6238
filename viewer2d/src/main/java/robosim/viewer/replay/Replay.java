package robosim.viewer.replay;

import java.io.IOException;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.RecordingException;
import robosim.protocol.recording.RecordingReader;
import robosim.viewer.draw.RenderedImages;

/**
 * Feeds a recording, step by step, to a {@link RenderedImages} as the live viewer feeds the wire:
 * the steps before the range only extend the trails, the steps in it are drawn (as the
 * {@code RenderedImages} says: every K-th, and the last), and reading stops after the range. A damaged recording is drawn up to its last good
 * step, and the damage is reported in the result rather than thrown.
 */
public final class Replay {
    private Replay() {
    }

    /**
     * What a replay drew.
     *
     * @param snapshotsRead  the snapshots read from the recording
     * @param imagesDrawn the images handed to the sink
     * @param firstStep   the first step in range, or -1 if none was
     * @param lastStep    the last step in range, or -1 if none was
     * @param problem     the damage that stopped the reading, or {@code null}
     */
    public record Result(long snapshotsRead, long imagesDrawn, long firstStep, long lastStep, RecordingException problem) {
    }

    /**
     * Draws the steps of a recording in a range.
     *
     * @param reader an open recording, positioned after its world
     * @param out    draws and stores the images; closed at the end, which draws the last step
     * @param range  the steps to draw
     * @return what was drawn, and the damage if the recording is damaged
     * @throws IOException if the images cannot be stored or the file cannot be read
     */
    public static Result run(RecordingReader reader, RenderedImages out, ReplayRange range) throws IOException {
        long read = 0;
        long first = -1;
        long last = -1;
        RecordingException problem = null;
        WorldDescription world = reader.world();
        out.world(world);
        try {
            Snapshot f;
            while ((f = reader.next()) != null && f.step() <= range.to()) {
                read++;
                if (reader.world() != world) {
                    world = reader.world();
                    out.world(world);
                }
                if (f.step() < range.from()) {
                    out.skip(f);
                    continue;
                }
                first = first < 0 ? f.step() : first;
                last = f.step();
                out.snapshot(f);
            }
        } catch (RecordingException e) {
            problem = e;
        }
        out.close();
        return new Result(read, out.written(), first, last, problem);
    }
}
