package robosim.cli;

import java.time.Duration;
import java.util.List;
import robosim.viewer.draw.PngImageWriter;
import robosim.viewer.draw.RenderOptions;
import robosim.viewer.draw.RenderedImages;
import robosim.viewer.net.ViewerClient;
import robosim.viewer.net.ViewerOptions;

/** Runs a PNG-writing viewer for the commands that need one. */
final class Viewers {
    private Viewers() {
    }

    static ViewerClient pngClient(String host, int port, PngImageWriter png, int every, int width, boolean sonar,
                                  boolean names, Duration readTimeout) {
        ViewerOptions options = ViewerOptions.of(host, port).withName("png:" + png.directory().getFileName())
                .withReadTimeout(readTimeout);
        return new ViewerClient(options, List.of(RenderedImages.flat(png, new RenderOptions(width, sonar, names), every)));
    }
}
