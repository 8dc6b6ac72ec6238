package robosim.cli;

import java.nio.file.Path;
import java.time.Duration;
import robosim.viewer.PngImageWriter;
import robosim.viewer.RenderOptions;
import robosim.viewer.ViewerClient;
import robosim.viewer.ViewerOptions;

/** Runs a PNG-writing viewer for the commands that need one. */
final class Viewers {
    private Viewers() {
    }

    static ViewerClient pngClient(String host, int port, Path dir, int every, int width, boolean sonar,
                                  boolean names, Duration readTimeout) {
        ViewerOptions options = ViewerOptions.of(host, port).withName("png:" + dir.getFileName())
                .withEvery(every).withRender(new RenderOptions(width, sonar, names))
                .withReadTimeout(readTimeout);
        return new ViewerClient(options, new PngImageWriter(dir));
    }
}
