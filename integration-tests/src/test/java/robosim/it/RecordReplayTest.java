package robosim.it;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.net.RunReport;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;
import robosim.protocol.recording.RecordingReader;
import robosim.protocol.recording.RecordingWriter;
import robosim.viewer.draw.SnapshotPainter;
import robosim.viewer.draw.PngImageWriter;
import robosim.viewer.draw.RenderedImages;
import robosim.viewer.draw.WorldRenderer;
import robosim.viewer.replay.Replay;
import robosim.viewer.replay.ReplayRange;

/**
 * A run recorded and replayed: the replay draws what the live viewer drew, pixel for pixel, and the
 * same deterministic run recorded twice gives the same bytes.
 */
@Timeout(value = 4, unit = TimeUnit.MINUTES)
class RecordReplayTest {
    private static final int STEPS = 60;

    @TempDir
    Path dir;

    private static int[] pixels(Path png) throws IOException {
        BufferedImage image = ImageIO.read(png.toFile());
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    private static Replay.Result replay(Path recording, Path pngDir) throws IOException {
        RenderedImages out = new RenderedImages(SnapshotPainter.flat(new WorldRenderer(), RecordedRun.RENDER),
                new PngImageWriter(pngDir), 1, false);
        try (RecordingReader reader = RecordingReader.open(recording)) {
            return Replay.run(reader, out, ReplayRange.ALL);
        }
    }

    @Test
    void replayedImagesEqualTheLiveViewersPixelForPixel() throws Exception {
        Path live = dir.resolve("live");
        Path envRecording = dir.resolve("env.rsr");
        Path viewerRecording = dir.resolve("viewer.rsr");
        RunReport report = RecordedRun.run(STEPS, envRecording, List.of(
                new RenderedImages(SnapshotPainter.flat(new WorldRenderer(), RecordedRun.RENDER), new PngImageWriter(live), 1, false),
                RecordingWriter.create(viewerRecording, true)));
        assertTrue(report.robots().get(0).distance() > 500, "r1 drove: " + report.robots().get(0));
        Replay.Result fromEnv = replay(envRecording, dir.resolve("from-env"));
        Replay.Result fromViewer = replay(viewerRecording, dir.resolve("from-viewer"));
        assertEquals(STEPS + 1, fromEnv.imagesDrawn());
        assertEquals(STEPS + 1, fromViewer.imagesDrawn());
        PngImageWriter names = new PngImageWriter(live);
        for (int step = 0; step <= STEPS; step++) {
            String file = names.fileFor(step).getFileName().toString();
            int[] drawnLive = pixels(live.resolve(file));
            assertArrayEquals(drawnLive, pixels(dir.resolve("from-viewer").resolve(file)),
                    "step " + step + " replayed from the viewer's recording");
            // the viewer attached before the robots had connected, and was sent step 0 again as the run started
            assertArrayEquals(drawnLive, pixels(dir.resolve("from-env").resolve(file)),
                    "step " + step + " replayed from the Environment's recording");
        }
    }

    @Test
    void theSameRunRecordedTwiceIsByteIdentical() throws Exception {
        Path first = dir.resolve("first.rsr");
        Path second = dir.resolve("second.rsr");
        RecordedRun.run(STEPS, first, List.of());
        RecordedRun.run(STEPS, second, List.of());
        assertTrue(Files.size(first) > 1000, "a real recording: " + Files.size(first) + " bytes");
        assertEquals(-1, Files.mismatch(first, second), "the two recordings differ at this byte offset");
        try (RecordingReader reader = RecordingReader.open(first)) {
            long snapshots = 0;
            while (reader.next() != null) {
                snapshots++;
            }
            assertEquals(STEPS + 1, snapshots);
            assertEquals("done: step limit " + STEPS + " reached", reader.endReason());
        }
    }

    @Test
    void aViewerAttachedBeforeTheRobotsRecordsTheSameRunAsTheEnvironment() throws Exception {
        Path envRecording = dir.resolve("env.rsr");
        Path viewerRecording = dir.resolve("viewer.rsr");
        RecordedRun.run(STEPS, envRecording, List.of(RecordingWriter.create(viewerRecording, true)));
        try (RecordingReader fromEnv = RecordingReader.open(envRecording);
             RecordingReader fromViewer = RecordingReader.open(viewerRecording)) {
            MessageCodec codec = new MessageCodec();
            for (int step = 0; step <= STEPS; step++) {
                Snapshot e = fromEnv.next();
                Snapshot v = fromViewer.next();
                assertEquals(step, v.step(), "one snapshot a step");
                assertArrayEquals(codec.encode(e), codec.encode(v), "step " + step);
            }
            assertTrue(fromViewer.next() == null);
        }
    }
}
