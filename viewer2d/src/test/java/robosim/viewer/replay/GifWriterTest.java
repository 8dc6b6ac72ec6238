package robosim.viewer.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Node;

/** An animated GIF that ImageIO reads back: its frames, their delay, and the loop extension. */
class GifWriterTest {
    @TempDir
    Path dir;

    private static BufferedImage filled(Color c) {
        BufferedImage image = new BufferedImage(40, 30, BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = image.createGraphics();
        g.setColor(c);
        g.fillRect(0, 0, 40, 30);
        g.dispose();
        return image;
    }

    @Test
    void aSecondImageOfAStepTakesTheFirstsPlace() throws IOException {
        Path file = dir.resolve("start.gif");
        try (GifWriter gif = new GifWriter(file, 100)) {
            gif.accept(0, filled(Color.RED)); // step 0 as a viewer attached before the robots saw it
            gif.accept(0, filled(Color.GREEN)); // step 0 again as the run started
            gif.accept(20, filled(Color.BLUE));
            assertEquals(2, gif.images());
        }
        try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
            reader.setInput(in);
            assertEquals(2, reader.getNumImages(true));
            assertEquals(new Color(0, 255, 0), new Color(reader.read(0).getRGB(20, 15)));
            assertEquals(new Color(0, 0, 255), new Color(reader.read(1).getRGB(20, 15)));
            reader.dispose();
        }
    }

    @Test
    void threeImagesLoopForEverAtTheStepLength() throws IOException {
        Path file = dir.resolve("anim/run.gif");
        try (GifWriter gif = new GifWriter(file, 100)) {
            gif.accept(0, filled(Color.RED));
            gif.accept(1, filled(Color.GREEN));
            gif.accept(2, filled(Color.BLUE));
            assertEquals(3, gif.images());
            assertEquals(10, gif.delayCentiseconds());
        }
        try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
            reader.setInput(in);
            assertEquals(3, reader.getNumImages(true));
            assertEquals(new Color(0, 255, 0), new Color(reader.read(1).getRGB(20, 15)));
            IIOMetadataNode first = (IIOMetadataNode) reader.getImageMetadata(0).getAsTree("javax_imageio_gif_image_1.0");
            assertEquals("10", find(first, "GraphicControlExtension").getAttribute("delayTime"));
            IIOMetadataNode app = find(first, "ApplicationExtension");
            assertEquals("NETSCAPE", app.getAttribute("applicationID"));
            assertEquals("2.0", app.getAttribute("authenticationCode"));
            byte[] loop = (byte[]) app.getUserObject();
            assertTrue(loop[0] == 1 && loop[1] == 0 && loop[2] == 0, "loop count 0: for ever");
            reader.dispose();
        }
    }

    @Test
    void aDelayShorterThanBrowsersHonourIsRaisedToTheirMinimum() throws IOException {
        try (GifWriter gif = new GifWriter(dir.resolve("fast.gif"), 5)) {
            gif.accept(0, filled(Color.WHITE));
            assertEquals(GifWriter.MIN_DELAY_CS, gif.delayCentiseconds());
        }
    }

    private static IIOMetadataNode find(Node node, String name) {
        if (node.getNodeName().equals(name)) {
            return (IIOMetadataNode) node;
        }
        for (Node c = node.getFirstChild(); c != null; c = c.getNextSibling()) {
            IIOMetadataNode found = find(c, name);
            if (found != null) {
                return found;
            }
        }
        return null;
    }
}
