package robosim.viewer.draw;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import javax.imageio.ImageIO;

/**
 * Writes each image to {@code DIR/frame-%06d.png}, named by its step, so that the files sort in
 * step order and a video tool can read them as a sequence. Creates the directory on first use.
 */
public final class PngImageWriter implements ImageSink {
    private final Path directory;
    private boolean created;
    private int imagesWritten;
    private long lastStep = -1;

    /** @param directory where the PNG files go; created, with its parents, if missing */
    public PngImageWriter(Path directory) {
        if (directory == null) {
            throw new IllegalArgumentException("null was supplied for directory: a directory is required");
        }
        this.directory = directory;
    }

    /**
     * The file a step's image is written to.
     *
     * @param step the step
     * @return {@code DIR/frame-NNNNNN.png}
     */
    public Path fileFor(long step) {
        return directory.resolve(String.format(Locale.ROOT, "frame-%06d.png", step));
    }

    /**
     * Writes one image, replacing any earlier file for the same step.
     *
     * @param step  the step the image shows
     * @param image the image
     * @throws IOException if the directory cannot be created or the file written
     */
    @Override
    public synchronized void accept(long step, BufferedImage image) throws IOException {
        write(step, image);
    }

    /**
     * Writes one image and says where.
     *
     * @param step  the step the image shows
     * @param image the image
     * @return the file written
     * @throws IOException if the directory cannot be created or the file written
     */
    public synchronized Path write(long step, BufferedImage image) throws IOException {
        if (!created) {
            Files.createDirectories(directory);
            created = true;
        }
        Path file = fileFor(step);
        if (!ImageIO.write(image, "png", file.toFile())) {
            throw new IOException("no PNG writer accepts an image of type " + image.getType()
                    + " for " + file);
        }
        if (step != lastStep) {
            imagesWritten++; // an image of the step just written (step 0, sent again as the run starts) replaces it
        }
        lastStep = step;
        return file;
    }

    /** @return the directory the images go to */
    public Path directory() {
        return directory;
    }

    /** @return how many images this writer has written, one a step: an image of the step just written replaced it */
    public synchronized int imagesWritten() {
        return imagesWritten;
    }
}
