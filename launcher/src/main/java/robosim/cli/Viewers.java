package robosim.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Locale;
import picocli.CommandLine.Model.CommandSpec;
import robosim.viewer.PngFrameWriter;
import robosim.viewer.RenderOptions;
import robosim.viewer.ViewerClient;
import robosim.viewer.ViewerException;
import robosim.viewer.ViewerOptions;
import robosim.viewer.ViewerSummary;

/** Runs a PNG-writing viewer for the commands that need one. */
final class Viewers {
    private Viewers() {
    }

    static ViewerClient pngClient(String host, int port, Path dir, int every, int width, boolean sonar,
                                  boolean names, Duration readTimeout) {
        ViewerOptions options = ViewerOptions.of(host, port).withName("png:" + dir.getFileName())
                .withEvery(every).withRender(new RenderOptions(width, sonar, names))
                .withReadTimeout(readTimeout);
        return new ViewerClient(options, new PngFrameWriter(dir));
    }

    static int run(CommandSpec spec, String host, int port, Path dir, int every, int width, boolean sonar,
                   boolean names) {
        PrintWriter out = spec.commandLine().getOut();
        try {
            ViewerClient client = pngClient(host, port, dir, every, width, sonar, names, Duration.ofMinutes(10));
            ViewerSummary s = client.run();
            out.printf(Locale.ROOT, "Viewer: world %s, %d frames received, %d PNG frames written to %s (%s)%n",
                    s.world(), s.framesReceived(), s.framesWritten(), dir.toAbsolutePath(), s.endReason());
            out.flush();
            return 0;
        } catch (IllegalArgumentException | ViewerException e) {
            spec.commandLine().getErr().println("robosim viewer: " + e.getMessage());
            return 1;
        }
    }
}
