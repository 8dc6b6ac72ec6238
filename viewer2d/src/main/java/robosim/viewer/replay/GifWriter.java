package robosim.viewer.replay;

import java.awt.image.BufferedImage;
import java.io.Closeable;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;
import robosim.viewer.draw.ImageSink;

/**
 * Writes images as one animated GIF, with ImageIO's GIF writer: every frame shown for the same
 * delay, and the NETSCAPE2.0 application extension so that viewers loop it for ever. Colours are
 * reduced to the GIF's 256 by ImageIO's own palette builder, frame by frame. A frame is written
 * when the next step's comes, or at the close: a second image of the same step (step 0, sent again
 * as the run starts) takes the first one's place.
 */
public final class GifWriter implements ImageSink, Closeable {
    /** The shortest delay browsers honour, in hundredths of a second; shorter ones they slow down. */
    public static final int MIN_DELAY_CS = 2;
    private static final String FORMAT = "javax_imageio_gif_image_1.0";

    private final Path file;
    private final int delayCs;
    private final ImageWriter writer;
    private final ImageOutputStream out;
    private int images;
    /** The latest frame, not yet written; null when there is none. */
    private BufferedImage pending;
    private long pendingStep;

    /**
     * Creates (or replaces) the file, with its parent directories.
     *
     * @param file    the GIF file
     * @param delayMs how long each frame shows, ms; rounded to hundredths of a second, at least
     *                {@value #MIN_DELAY_CS}
     * @throws IOException if the file cannot be created or no GIF writer is installed
     */
    public GifWriter(Path file, long delayMs) throws IOException {
        if (delayMs < 1) {
            throw new IllegalArgumentException(delayMs + " was supplied for delayMs: it must be at least 1 ms");
        }
        Iterator<ImageWriter> writers = ImageIO.getImageWritersByFormatName("gif");
        if (!writers.hasNext()) {
            throw new IOException("no GIF writer is installed in this Java runtime");
        }
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        Files.deleteIfExists(file);
        this.file = file;
        this.delayCs = (int) Math.max(MIN_DELAY_CS, Math.min(65535, Math.round(delayMs / 10.0)));
        this.writer = writers.next();
        this.out = ImageIO.createImageOutputStream(file.toFile());
        if (out == null) {
            writer.dispose();
            throw new IOException("cannot open " + file + " for writing");
        }
        writer.setOutput(out);
        writer.prepareWriteSequence(null);
    }

    /**
     * Adds one frame to the animation.
     *
     * @param step  the step the image shows
     * @param image the image
     * @throws IOException if the frame cannot be written
     */
    @Override
    public void accept(long step, BufferedImage image) throws IOException {
        if (pending != null && pendingStep != step) {
            write(pending);
        }
        pending = image;
        pendingStep = step;
    }

    private void write(BufferedImage image) throws IOException {
        ImageWriteParam param = writer.getDefaultWriteParam();
        IIOMetadata metadata = writer.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(image), param);
        IIOMetadataNode root = (IIOMetadataNode) metadata.getAsTree(FORMAT);
        IIOMetadataNode control = child(root, "GraphicControlExtension");
        control.setAttribute("disposalMethod", "none");
        control.setAttribute("userInputFlag", "FALSE");
        control.setAttribute("transparentColorFlag", "FALSE");
        control.setAttribute("delayTime", Integer.toString(delayCs));
        control.setAttribute("transparentColorIndex", "0");
        if (images == 0) {
            IIOMetadataNode loop = new IIOMetadataNode("ApplicationExtension");
            loop.setAttribute("applicationID", "NETSCAPE");
            loop.setAttribute("authenticationCode", "2.0");
            loop.setUserObject(new byte[] {1, 0, 0});
            child(root, "ApplicationExtensions").appendChild(loop);
        }
        metadata.setFromTree(FORMAT, root);
        writer.writeToSequence(new IIOImage(image, null, metadata), param);
        images++;
    }

    private static IIOMetadataNode child(IIOMetadataNode parent, String name) {
        for (int i = 0; i < parent.getLength(); i++) {
            if (parent.item(i).getNodeName().equals(name)) {
                return (IIOMetadataNode) parent.item(i);
            }
        }
        IIOMetadataNode node = new IIOMetadataNode(name);
        parent.appendChild(node);
        return node;
    }

    /** @return the frames so far, the latest included */
    public int images() {
        return images + (pending != null ? 1 : 0);
    }

    /** @return each frame's delay, hundredths of a second */
    public int delayCentiseconds() {
        return delayCs;
    }

    /** @return the GIF file */
    public Path file() {
        return file;
    }

    /**
     * Ends the animation and closes the file.
     *
     * @throws IOException if the GIF trailer cannot be written
     */
    @Override
    public void close() throws IOException {
        try {
            if (pending != null) {
                BufferedImage last = pending;
                pending = null;
                write(last);
            }
            writer.endWriteSequence();
        } finally {
            writer.dispose();
            out.close();
        }
    }
}
