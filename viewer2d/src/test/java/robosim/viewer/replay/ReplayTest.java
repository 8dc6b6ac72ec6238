package robosim.viewer.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.recording.RecordingReader;
import robosim.viewer.draw.SnapshotPainter;
import robosim.viewer.draw.RenderOptions;
import robosim.viewer.draw.RenderedImages;
import robosim.viewer.draw.WorldRenderer;

/** Replay draws the chosen steps of a recording through the live viewer's renderer. */
class ReplayTest {
    private static final RenderOptions OPTIONS = RenderOptions.of(400);

    @TempDir
    Path dir;

    private final List<Long> drawn = new ArrayList<>();
    private final List<BufferedImage> images = new ArrayList<>();

    private Replay.Result replay(Path file, int every, ReplayRange range) throws IOException {
        RenderedImages out = new RenderedImages(SnapshotPainter.flat(new WorldRenderer(), OPTIONS), (step, image) -> {
            drawn.add(step);
            images.add(image);
        }, every, false);
        try (RecordingReader reader = RecordingReader.open(file)) {
            return Replay.run(reader, out, range);
        }
    }

    @Test
    void everyStepIsDrawnAsTheLiveViewerDrawsIt() throws IOException {
        Replay.Result r = replay(Recorded.write(dir.resolve("run.rsr"), true), 1, ReplayRange.ALL);
        assertEquals(List.of(0L, 1L, 2L, 3L, 4L, 5L, 6L, 7L, 8L, 9L, 10L, 11L, 12L), drawn);
        assertEquals(new Replay.Result(13, 13, 0, 12, null), r);
        BufferedImage live = new WorldRenderer().render(Recorded.world(), Recorded.snapshot(7), OPTIONS);
        BufferedImage replayed = images.get(7);
        int[] a = live.getRGB(0, 0, live.getWidth(), live.getHeight(), null, 0, live.getWidth());
        int[] b = replayed.getRGB(0, 0, live.getWidth(), live.getHeight(), null, 0, live.getWidth());
        assertTrue(Arrays.equals(a, b), "the replayed step 7 equals the live drawing pixel for pixel");
    }

    @Test
    void fromToAndEveryChooseTheStepsAndTheLastInRangeIsAlwaysDrawn() throws IOException {
        Replay.Result r = replay(Recorded.write(dir.resolve("run.rsr"), true), 3, new ReplayRange(2, 10));
        assertEquals(List.of(3L, 6L, 9L, 10L), drawn);
        assertEquals(2, r.firstStep());
        assertEquals(10, r.lastStep());
        assertEquals(11, r.snapshotsRead(), "reading stops after the range");
    }

    @Test
    void aCutShortRecordingIsDrawnToItsLastWholeStepAndTheProblemReturned() throws IOException {
        Path whole = Recorded.write(dir.resolve("whole.rsr"), false);
        byte[] bytes = Files.readAllBytes(whole);
        Path cut = dir.resolve("cut.rsr");
        Files.write(cut, Arrays.copyOf(bytes, bytes.length - 3));
        Replay.Result r = replay(cut, 5, ReplayRange.ALL);
        assertTrue(r.problem() != null && r.problem().truncated(), String.valueOf(r.problem()));
        assertEquals(11, r.problem().lastGoodStep(), "step 12's record lost its last 3 bytes");
        assertEquals(List.of(0L, 5L, 10L, 11L), drawn, "every 5th and the last good step");
    }

    @Test
    void aRangeAfterTheEndDrawsNothing() throws IOException {
        Replay.Result r = replay(Recorded.write(dir.resolve("run.rsr"), false), 1, new ReplayRange(50, 60));
        assertEquals(List.of(), drawn);
        assertEquals(-1, r.firstStep());
        assertNull(r.problem());
    }
}
