package robosim.viewer.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.recording.Recording;
import robosim.protocol.recording.RecordingWriter;

/** The replay window: play, pause, step, jump and speed, driven as the buttons drive them. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class ReplayWindowTest {
    @TempDir
    Path dir;

    private Recording recording() throws Exception {
        Path file = dir.resolve("run.rsr");
        try (RecordingWriter w = RecordingWriter.create(file, true)) {
            w.world(Scenes.world());
            for (int step = 0; step <= 20; step++) {
                w.snapshot(Scenes.snapshot(step));
            }
            w.end("done");
        }
        return Recording.read(file);
    }

    @Test
    void stepJumpAndPlayMoveThroughTheRecording() throws Exception {
        Recording recording = recording();
        ViewModel model = new ViewModel();
        Scenes.onEdt(() -> {
            ReplayPlayer player = new ReplayPlayer(recording, model);
            ViewerPane pane = new ViewerPane(model, new ViewState(), player);
            assertEquals(0, model.snapshot().step(), "opens at the first step, paused");
            assertFalse(player.playing());
            player.step(1);
            player.step(1);
            assertEquals(2, model.snapshot().step());
            assertEquals(3, model.trails().points("r1").length / 2, "trails grow with each step");
            player.seek(15);
            assertEquals(15, model.snapshot().step());
            assertEquals(15, pane.playbackControls().positionSlider().getValue());
            assertEquals(16, model.trails().points("r1").length / 2, "a jump rebuilds the trails to that step");
            player.step(-1);
            assertEquals(14, model.snapshot().step());
            pane.playbackControls().playButton().doClick();
            assertTrue(player.playing());
            assertEquals("Pause", pane.playbackControls().playButton().getText());
            player.setSpeed(64);
            assertEquals(13, player.stepsPerTick(), "at 64x a 100 ms step lasts 1.6 ms: 13 steps per 20 ms tick");
            player.tick();
            assertEquals(20, model.snapshot().step(), "the last step, and no further");
            assertFalse(player.playing(), "playing stops at the end");
            assertTrue(StatusBar.text(model).startsWith("world fixture · step 20 · t = 2.0 s"), StatusBar.text(model));
            assertTrue(StatusBar.text(model).contains("replay of run.rsr"), StatusBar.text(model));
            return null;
        });
    }

    @Test
    void theReplayPaneScreenshotShowsTheWorldAndTheControls() throws Exception {
        Recording recording = recording();
        ViewModel model = new ViewModel();
        int differing = Scenes.onEdt(() -> {
            ReplayPlayer player = new ReplayPlayer(recording, model);
            ViewerPane pane = new ViewerPane(model, new ViewState(), player);
            java.awt.image.BufferedImage first = pane.screenshot(900, 650);
            player.seek(20);
            java.awt.image.BufferedImage last = pane.screenshot(900, 650);
            int n = 0;
            for (int y = 0; y < 650; y++) {
                for (int x = 0; x < 900; x++) {
                    n += first.getRGB(x, y) != last.getRGB(x, y) ? 1 : 0;
                }
            }
            return n;
        });
        assertTrue(differing > 500, "the robot moved on screen: " + differing + " pixels changed");
    }
}
