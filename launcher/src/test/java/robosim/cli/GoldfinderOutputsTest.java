package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import robosim.protocol.recording.Recording;

/**
 * {@code goldfinder --record FILE --gif FILE} (and so {@code demo}'s): one viewer writes the PNG
 * frames, the GIF of the same frames, and a recording of every step, on a small maze run by threads.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class GoldfinderOutputsTest {
    @TempDir
    Path dir;

    private String[] run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        int exit = cl.execute(args);
        return new String[] {Integer.toString(exit), out.toString(), err.toString()};
    }

    private Path maze() {
        Path world = dir.resolve("maze.xml");
        String[] made = run("maze", "--cells", "4", "4", "--cell-size", "1500", "--seed", "3", "--robots", "2",
                "--out", world.toString());
        assertEquals("0", made[0], made[2]);
        return world;
    }

    @Test
    void aWorldThatDoesNotGiveItsCellSizeIsRefusedBeforeTheRun() throws Exception {
        Path world = maze();
        Path without = dir.resolve("no-cell-size.xml");
        Files.writeString(without, Files.readString(world).replaceAll("\\s*<property name=\"cellSize\"[^>]*/>", ""));
        String[] r = run("goldfinder", without.toString(), "--robots", "2", "--no-frames");
        assertEquals("1", r[0]);
        assertTrue(r[2].contains("has no <property name=\"cellSize\" value=\"MM\"/>"), r[2]);
        assertFalse(r[1].contains("Gold found"), "no run: " + r[1]);
    }

    @Test
    void theRunIsRecordedAndItsFramesMadeIntoAGif() throws Exception {
        Path world = maze();
        Path recording = dir.resolve("run.rsr");
        Path gif = dir.resolve("run.gif");
        String[] r = run("goldfinder", world.toString(), "--robots", "2", "--steps", "60", "--every", "20",
                "--out-dir", dir.resolve("out").toString(), "--record", recording.toString(), "--gif", gif.toString());
        assertTrue(r[0].equals("0") || r[0].equals("3"), "found or not found, no failure: " + r[0] + "\n" + r[2]);

        Recording read = Recording.read(recording);
        assertTrue(read.complete(), "the recording has its end record");
        assertEquals(61, read.snapshots().size(), "steps 0 to 60");

        try (Stream<Path> frames = Files.list(dir.resolve("out/frames"))) {
            assertEquals(4, frames.count(), "PNG frames at steps 0, 20, 40, 60");
        }
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            Iterator<ImageReader> readers = ImageIO.getImageReaders(in);
            ImageReader reader = readers.next();
            reader.setInput(in);
            assertEquals(4, reader.getNumImages(true), "the GIF holds the same four frames");
            assertEquals(RunOutputs.GIF_WIDTH, reader.getWidth(1), "the frames drawn 480 px wide");
            reader.dispose();
        }
        assertTrue(r[1].contains("GIF: 4 frames, 100 ms each, looping, written to " + gif.toAbsolutePath()), r[1]);
        assertTrue(r[1].contains("Recording: " + recording.toAbsolutePath() + ", 61 steps"), r[1]);
    }

    @Test
    void aRecordingWithoutFramesWritesNoPngFiles() throws Exception {
        Path world = maze();
        Path recording = dir.resolve("only.rsr");
        String[] r = run("goldfinder", world.toString(), "--robots", "2", "--steps", "30", "--no-frames",
                "--out-dir", dir.resolve("out").toString(), "--record", recording.toString());
        assertTrue(r[0].equals("0") || r[0].equals("3"), r[2]);
        assertEquals(31, Recording.read(recording).snapshots().size());
        assertFalse(r[1].contains("PNG files"), r[1]);
    }

    @Test
    void aGifThatCannotBeCreatedIsAOneLineErrorNamingTheFile() throws Exception {
        Path world = maze();
        Path notAFolder = Files.writeString(dir.resolve("not-a-folder"), "a file");
        Path gif = notAFolder.resolve("run.gif");
        String[] r = run("goldfinder", world.toString(), "--robots", "2", "--steps", "10",
                "--out-dir", dir.resolve("out").toString(), "--gif", gif.toString());
        assertEquals("1", r[0]);
        assertTrue(r[2].startsWith("robosim goldfinder: cannot create GIF " + gif), r[2]);
        assertFalse(r[2].contains("\tat "), r[2]);
    }
}
