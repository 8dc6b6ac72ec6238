package robosim.viewer.draw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

@Timeout(value = 30, unit = TimeUnit.SECONDS)
class PngImageWriterTest {
    @TempDir
    Path tmp;

    @Test
    void writesAReadablePngNamedByStepIntoANewDirectory() throws IOException {
        PngImageWriter writer = new PngImageWriter(tmp.resolve("run/frames"));
        BufferedImage image = new BufferedImage(64, 32, BufferedImage.TYPE_INT_RGB);
        image.setRGB(5, 7, 0x1f77b4);

        Path file = writer.write(7, image);

        assertEquals(tmp.resolve("run/frames/frame-000007.png"), file);
        assertTrue(Files.isRegularFile(file));
        BufferedImage back = ImageIO.read(file.toFile());
        assertEquals(64, back.getWidth());
        assertEquals(32, back.getHeight());
        assertEquals(0x1f77b4, back.getRGB(5, 7) & 0xffffff);
        assertEquals(1, writer.imagesWritten());
    }

    @Test
    void writesARenderedImageAtItsSize() throws IOException {
        PngImageWriter writer = new PngImageWriter(tmp);
        writer.accept(120, new WorldRenderer().render(Fixtures.world(),
                Fixtures.snapshot(120, Fixtures.robotAtRest()), RenderOptions.of(Fixtures.WIDTH_PX)));
        BufferedImage back = ImageIO.read(writer.fileFor(120).toFile());
        assertEquals(800, back.getWidth());
        assertEquals(400 + WorldRenderer.keyHeight(Fixtures.world(), RenderOptions.of(800), 800), back.getHeight(),
                "the world and the key under it");
    }

    @Test
    void stepsPastSixDigitsKeepAllTheirDigits() {
        assertEquals("frame-1234567.png", new PngImageWriter(tmp).fileFor(1_234_567).getFileName().toString());
    }
}
