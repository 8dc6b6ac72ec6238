package robosim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robosim.protocol.recording.Recording;
import robosim.protocol.recording.RecordingException;
import robosim.protocol.Snapshot;
import robosim.protocol.recording.RecordingReader;
import robosim.viewer.draw.ImageSink;
import robosim.viewer.draw.PngImageWriter;
import robosim.viewer.draw.RenderedImages;
import robosim.viewer.replay.GifWriter;
import robosim.viewer.replay.RecordingSummary;
import robosim.viewer.replay.Replay;
import robosim.viewer.replay.ReplayRange;
import robosim.viewer.window.ReplayPlayer;
import robosim.viewer.window.ViewModel;
import robosim.viewer.window.ViewerPane;

/** {@code robosim replay}: draws, animates, sums up or plays back a recording, without an Environment. */
@Command(name = "replay", mixinStandardHelpOptions = true,
        description = "Replay a recording (made with env --record or viewer --record) without an Environment: PNG frames, an animated GIF, a summary, or a window.")
final class ReplayCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "FILE", description = "the recording")
    Path file;

    @Option(names = "--png-dir", paramLabel = "DIR", description = OptionTexts.PNG_DIR)
    Path pngDir;

    @Option(names = "--gif", paramLabel = "FILE", description = "write an animated GIF that loops")
    Path gif;

    @Option(names = "--info", description = "print the world, robots, steps, distance travelled and collisions")
    boolean info;

    @Option(names = "--window", description = OptionTexts.WINDOW + "; with play, pause, step and speed")
    boolean window;

    @Option(names = "--from", defaultValue = "0", paramLabel = "STEP", description = "first step drawn; default ${DEFAULT-VALUE}")
    long from;

    @Option(names = "--to", paramLabel = "STEP", description = "last step drawn; default the last")
    Long to;

    @Option(names = "--every", defaultValue = OptionTexts.EVERY_DEFAULT, paramLabel = "K", description = OptionTexts.EVERY)
    int every;

    @Option(names = "--speed", defaultValue = "1", paramLabel = "X",
            description = "GIF: playback speed as a multiple of simulated time (each frame shows K x step length / X); default ${DEFAULT-VALUE}")
    double speed;

    @Mixin
    DrawingOptions drawing;

    @Mixin
    QuietOption quiet;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (pngDir == null && gif == null && !info && !window) {
            throw new ParameterException(spec.commandLine(),
                    "Missing required option: at least one of '--png-dir=DIR', '--gif=FILE', '--info' or '--window'");
        }
        ReplayRange range;
        try {
            range = new ReplayRange(from, to == null ? Long.MAX_VALUE : to);
            if (every < 1 || !(speed > 0) || Double.isInfinite(speed)) {
                throw new IllegalArgumentException(every < 1 ? every + " was supplied for --every: it must be at least 1"
                        : speed + " was supplied for --speed: it must be greater than 0");
            }
            drawing.validate();
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        if (window && !Windows.prepare(err, "robosim replay")) {
            return 1;
        }
        if (!Files.isRegularFile(file)) {
            err.println("robosim replay: " + file + " is not a file");
            return 1;
        }
        int status = 0;
        try {
            if (info) {
                status = Math.max(status, info(out, err));
            }
            if (pngDir != null || gif != null) {
                status = Math.max(status, draw(out, err, range));
            }
            if (window) {
                status = Math.max(status, showWindow(err));
            }
        } catch (RecordingException e) {
            err.println("robosim replay: " + e.getMessage());
            return 1;
        } catch (IOException e) {
            err.println("robosim replay: " + e.getMessage());
            return 1;
        }
        return status;
    }

    private int info(PrintWriter out, PrintWriter err) throws IOException {
        RecordingSummary s;
        int version;
        try (RecordingReader reader = RecordingReader.open(file)) {
            version = reader.version();
            s = RecordingSummary.of(reader);
        }
        long bytes = Files.size(file);
        out.printf(Locale.ROOT, "Recording: %s (format %d, %d bytes, %s)%n", file, version, bytes,
                s.sensors() ? "sensors kept" : "without sensors");
        out.printf(Locale.ROOT, "World: %s, %.0f x %.0f mm, %d ms steps, %d walls and obstacles%n", s.world(), s.width(),
                s.height(), s.stepMs(), s.obstacles());
        out.printf(Locale.ROOT, "Steps: %d to %d (%d frames), %.1f s simulated, %.0f bytes per step%n", s.firstStep(),
                s.lastStep(), s.snapshots(), s.timeMs() / 1000.0, s.snapshots() == 0 ? 0.0 : (double) bytes / s.snapshots());
        out.printf(Locale.ROOT, "Ended: %s%n", s.endReason() != null ? s.endReason()
                : "abruptly after step " + s.lastStep() + " (no end record)");
        out.printf(Locale.ROOT, "Messages: %d sent, %d said%n", s.messages(), s.said());
        for (RecordingSummary.RobotTotals r : s.robots()) {
            out.printf(Locale.ROOT, "robot %s (%s): travelled %.0f mm, collisions %d, last pose (%.0f, %.0f, %.1f)%n",
                    r.name(), r.type(), r.distance(), r.collisions(), r.x(), r.y(), r.th());
        }
        for (Snapshot.Event e : s.events()) {
            out.printf(Locale.ROOT, "robot %s %s at step %d%s%n", e.robot(), e.what(), e.step(),
                    e.reason().isEmpty() ? "" : ": " + e.reason());
        }
        out.flush();
        return problem(err, s.problem());
    }

    private int draw(PrintWriter out, PrintWriter err, ReplayRange range) throws IOException {
        PngImageWriter png = pngDir == null ? null : new PngImageWriter(pngDir);
        Replay.Result result;
        GifWriter gifWriter = null;
        FrameProgress progress = FrameProgress.on(err, quiet.quiet, "replay", () -> 0);
        try (RecordingReader reader = RecordingReader.open(file)) {
            if (gif != null) {
                gifWriter = new GifWriter(gif, Math.round(reader.world().stepMs() * (double) every / speed));
            }
            GifWriter g = gifWriter;
            ImageSink sink = (step, image) -> {
                if (progress != null) {
                    progress.step(step);
                }
                if (png != null) {
                    png.accept(step, image);
                }
                if (g != null) {
                    g.accept(step, image);
                }
            };
            result = Replay.run(reader, new RenderedImages(drawing.painter(), sink, every, drawing.trails), range);
        } finally {
            if (progress != null) {
                progress.close();
            }
            if (gifWriter != null) {
                gifWriter.close();
            }
        }
        String steps = result.firstStep() < 0 ? "no step in range" : "steps " + result.firstStep() + " to " + result.lastStep();
        if (png != null) {
            out.printf(Locale.ROOT, "Replay: %d PNG frames (%s) written to %s%n", png.imagesWritten(), steps,
                    pngDir.toAbsolutePath());
        }
        if (gifWriter != null) {
            out.printf(Locale.ROOT, "GIF: %d frames (%s), %d ms each, looping, written to %s (%d bytes)%n",
                    gifWriter.images(), steps, gifWriter.delayCentiseconds() * 10, gif.toAbsolutePath(), Files.size(gif));
        }
        out.flush();
        return problem(err, result.problem());
    }

    private int showWindow(PrintWriter err) throws IOException, InterruptedException {
        Recording recording = Recording.read(file);
        int status = problem(err, recording.problem());
        ViewModel model = new ViewModel();
        Windows.open("RoboSim replay - " + file.getFileName(), () -> {
            ReplayPlayer player = new ReplayPlayer(recording, model);
            return new ViewerPane(model, drawing.windowState(), player);
        }).awaitClosed();
        return status;
    }

    /** Reports damage: a recording cut short is a warning, bad bytes an error. */
    private static int problem(PrintWriter err, RecordingException problem) {
        if (problem == null) {
            return 0;
        }
        err.println("robosim replay: " + (problem.truncated() ? "warning: " : "") + problem.getMessage());
        err.flush();
        return problem.truncated() ? 0 : 1;
    }
}
