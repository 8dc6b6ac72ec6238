package robosim.viewer.draw;

import java.awt.image.BufferedImage;
import java.io.IOException;

/**
 * Receives the images a {@link RenderedImages} draws: a PNG directory, a window, a video encoder.
 */
@FunctionalInterface
public interface ImageSink {
    /**
     * Takes one rendered image. The image is the sink's to keep; the client does not reuse it.
     *
     * @param step  the simulation step the image shows
     * @param image the rendered image
     * @throws IOException if the sink cannot store the image; the client then stops
     */
    void accept(long step, BufferedImage image) throws IOException;
}
