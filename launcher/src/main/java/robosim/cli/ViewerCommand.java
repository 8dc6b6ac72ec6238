package robosim.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robosim.protocol.recording.SnapshotListener;
import robosim.protocol.recording.RecordingWriter;
import robosim.viewer.draw.PngImageWriter;
import robosim.viewer.draw.RenderedImages;
import robosim.viewer.net.ViewerClient;
import robosim.viewer.net.ViewerException;
import robosim.viewer.net.ViewerOptions;
import robosim.viewer.net.ViewerSummary;
import robosim.viewer.window.LiveFeed;
import robosim.viewer.window.ViewModel;
import robosim.viewer.window.ViewState;
import robosim.viewer.window.ViewerPane;
import robosim.viewer.window.ViewerWindow;

/** {@code robosim viewer}: attaches to a running Environment; writes PNG frames, records, or shows a window. */
@Command(name = "viewer", mixinStandardHelpOptions = true,
        description = "Attach to a running Environment: write its frames as PNG files (--png-dir), record the run (--record), show it in a window (--window), or all at once.")
final class ViewerCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Mixin
    ViewerPortOptions at;

    @Mixin
    SecretOption secret;

    @Option(names = "--png-dir", paramLabel = "DIR", description = OptionTexts.PNG_DIR)
    Path pngDir;

    @Option(names = "--every", defaultValue = OptionTexts.EVERY_DEFAULT, paramLabel = "K", description = OptionTexts.EVERY)
    int every;

    @Mixin
    RecordOptions recording;

    @Option(names = "--window", description = OptionTexts.WINDOW + "; wheel zooms, drag pans (turns the camera in 3D)")
    boolean window;

    @Mixin
    DrawingOptions drawing;

    @Mixin
    QuietOption quiet;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (pngDir == null && !recording.requested() && !window) {
            throw new ParameterException(spec.commandLine(),
                    "Missing required option: at least one of '--png-dir=DIR', '--record=FILE' or '--window'");
        }
        List<SnapshotListener> listeners = new ArrayList<>();
        ViewerOptions options;
        try {
            drawing.validate();
            String bad = secret.apply();
            if (bad != null) {
                throw new IllegalArgumentException(bad);
            }
            RenderedImages.requireEvery(every);
            options = ViewerOptions.of(at.host, at.port()).withName(name())
                    .withReadTimeout(Duration.ofMinutes(10));
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        if (window && !Windows.prepare(err, "robosim viewer")) {
            return 1;
        }
        PngImageWriter png = pngDir == null ? null : new PngImageWriter(pngDir);
        if (png != null) {
            listeners.add(new RenderedImages(drawing.painter(), png, every, drawing.trails));
        }
        RecordingWriter recorder = null;
        if (recording.requested()) {
            recorder = recording.create(err, "viewer");
            if (recorder == null) {
                return 1;
            }
            listeners.add(recorder);
        }
        ViewModel model = new ViewModel();
        if (window) {
            listeners.add(new LiveFeed(model));
        }
        FrameProgress progress = FrameProgress.on(err, quiet.quiet, "viewer", () -> png == null ? 0 : png.imagesWritten());
        if (progress != null) {
            listeners.add(progress);
        }
        ViewerClient client = new ViewerClient(options, listeners);
        ViewerSummary s;
        try {
            s = window ? runWithWindow(client, model) : client.run();
        } catch (ViewerException | IllegalStateException e) {
            if (progress != null) {
                progress.close();
            }
            err.println("robosim viewer: " + e.getMessage());
            return 1;
        }
        if (progress != null) {
            progress.close();
        }
        if (png != null) {
            out.printf(Locale.ROOT, "Viewer: world %s, %d frames received, %d PNG frames written to %s (%s)%n",
                    s.world(), s.snapshotsReceived(), png.imagesWritten(), pngDir.toAbsolutePath(), s.endReason());
        } else {
            out.printf(Locale.ROOT, "Viewer: world %s, %d frames received (%s)%n", s.world(), s.snapshotsReceived(),
                    s.endReason());
        }
        out.flush();
        return recorder == null ? 0 : recording.report(out, err, "viewer", recorder);
    }

    private String name() {
        return window ? "window" : pngDir != null ? "png:" + pngDir.getFileName() : "recorder";
    }

    /** Shows the window, runs the client beside it, and stops the client when the window closes. */
    private ViewerSummary runWithWindow(ViewerClient client, ViewModel model) throws Exception {
        ViewState state = drawing.windowState();
        model.source("live from " + client.options().peer());
        ViewerWindow w = Windows.open("RoboSim viewer - " + client.options().peer(), () -> new ViewerPane(model, state));
        CompletableFuture<ViewerSummary> run = Background.supply("viewer", () -> {
            try {
                return client.run();
            } catch (ViewerException e) {
                throw new CompletionException(e);
            }
        });
        run.whenComplete((summary, failure) -> {
            if (failure != null) {
                Throwable cause = failure.getCause() == null ? failure : failure.getCause();
                javax.swing.SwingUtilities.invokeLater(() -> model.ended(cause.getMessage()));
            }
        });
        w.awaitClosed();
        client.stop();
        try {
            return run.join();
        } catch (CompletionException e) {
            if (e.getCause() instanceof ViewerException v) {
                throw v;
            }
            throw e;
        }
    }
}
