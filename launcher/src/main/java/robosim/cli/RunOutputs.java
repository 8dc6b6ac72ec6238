package robosim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import robosim.protocol.recording.RecordingWriter;
import robosim.protocol.recording.SnapshotListener;
import robosim.viewer.draw.PngImageWriter;
import robosim.viewer.draw.RenderOptions;
import robosim.viewer.draw.RenderedImages;
import robosim.viewer.replay.GifWriter;

/**
 * What the viewer of a {@code goldfinder} or {@code demo} run writes: PNG frames, an animated GIF
 * of the same frames, a recording; any of them, all fed by one viewer.
 */
final class RunOutputs implements AutoCloseable {
    private final PngImageWriter png;
    private final GifWriter gif;
    private final RecordingWriter recorder;
    private final RecordOptions recording;
    private boolean gifClosed;

    private RunOutputs(PngImageWriter png, GifWriter gif, RecordingWriter recorder, RecordOptions recording) {
        this.png = png;
        this.gif = gif;
        this.recorder = recorder;
        this.recording = recording;
    }

    /**
     * Opens the outputs asked for.
     *
     * @param err        where a failure is told
     * @param cmd        the command's name, for the error line
     * @param frames     the PNG frames' folder, or null for none
     * @param gifFile    the GIF, or null for none
     * @param gifDelayMs how long each GIF frame shows
     * @param recording  the recording options
     * @return the outputs, or null if one cannot be created (the reason is printed)
     */
    static RunOutputs open(PrintWriter err, String cmd, Path frames, Path gifFile, long gifDelayMs,
                           RecordOptions recording) {
        RecordingWriter recorder = null;
        if (recording.requested()) {
            recorder = recording.create(err, cmd);
            if (recorder == null) {
                return null;
            }
        }
        GifWriter gif = null;
        if (gifFile != null) {
            try {
                gif = new GifWriter(gifFile, gifDelayMs);
            } catch (IOException e) {
                err.println("robosim " + cmd + ": cannot create GIF " + gifFile + ": " + e.getMessage());
                closeQuietly(recorder);
                return null;
            }
        }
        return new RunOutputs(frames == null ? null : new PngImageWriter(frames), gif, recorder, recording);
    }

    /** The GIF's width, px: small enough to share, and to encode while the run goes on. */
    static final int GIF_WIDTH = 480;

    /**
     * @param every draw every K-th step
     * @param width the PNG images' width, px
     * @param drawings whether the images show the robots' drawings
     * @return the viewer's listeners: the PNG drawing, the GIF's drawing of the same steps
     *         {@value #GIF_WIDTH} px wide (each on a thread of its own), and the recorder
     */
    List<SnapshotListener> listeners(int every, int width, boolean drawings) {
        List<SnapshotListener> listeners = new ArrayList<>();
        if (png != null) {
            listeners.add(new QueuedListener("png frames",
                    RenderedImages.flat(png, new RenderOptions(width, false, true).withDrawings(drawings), every)));
        }
        if (gif != null) {
            listeners.add(new QueuedListener("gif frames",
                    RenderedImages.flat(gif, new RenderOptions(GIF_WIDTH, false, true).withDrawings(drawings),
                            every)));
        }
        if (recorder != null) {
            listeners.add(recorder);
        }
        return listeners;
    }

    /**
     * Finishes the GIF and prints what was written, after the viewer has ended.
     *
     * @param out standard output
     * @param err standard error
     * @param cmd the command's name, for error lines
     * @return 0, or 1 if the GIF or the recording could not be written whole
     * @throws IOException if the GIF cannot be finished
     */
    int report(PrintWriter out, PrintWriter err, String cmd) throws IOException {
        if (png != null) {
            out.printf(Locale.ROOT, "Frames: %d PNG files in %s%n", png.imagesWritten(), png.directory().toAbsolutePath());
        }
        if (gif != null) {
            closeGif();
            out.printf(Locale.ROOT, "GIF: %d frames, %d ms each, looping, written to %s (%d bytes)%n", gif.images(),
                    gif.delayCentiseconds() * 10, gif.file().toAbsolutePath(), Files.size(gif.file()));
        }
        out.flush();
        return recorder == null ? 0 : recording.report(out, err, cmd, recorder);
    }

    private void closeGif() throws IOException {
        if (!gifClosed) {
            gifClosed = true;
            gif.close();
        }
    }

    @Override
    public void close() throws IOException {
        try {
            if (gif != null) {
                closeGif();
            }
        } finally {
            if (recorder != null) {
                recorder.close();
            }
        }
    }

    private static void closeQuietly(RecordingWriter recorder) {
        if (recorder != null) {
            try {
                recorder.close();
            } catch (IOException e) {
                // the recording is abandoned: the GIF's failure is the one reported
            }
        }
    }
}
