package robosim.viewer.draw;

import java.awt.image.BufferedImage;
import java.io.IOException;

/**
 * Receives the images a {@link RenderedImages} draws: a PNG directory, a window, a video encoder.
 */
@FunctionalInterface
public interface ImageSink {
    /**
     * Takes one rendered image. The image is the sink's to keep; the caller does not reuse it.
     *
     * @param step  the simulation step the image shows
     * @param image the rendered image
     * @throws IOException if the sink cannot store the image; the run being drawn then stops
     */
    void accept(long step, BufferedImage image) throws IOException;
}
