package robosim.viewer.window;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** Frames from the network thread reach the model on the event thread, in order, none lost. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class LiveFeedTest {
    @Test
    void aFastRunArrivesWholeAndInOrder() throws Exception {
        ViewModel model = new ViewModel();
        LiveFeed feed = new LiveFeed(model);
        Thread network = new Thread(() -> {
            feed.world(Scenes.world());
            for (int step = 0; step <= 200; step++) {
                feed.snapshot(Scenes.snapshot(step));
            }
            feed.end("done: step limit 200 reached");
            feed.close();
        });
        network.start();
        network.join(10_000);
        String ended = Scenes.onEdt(model::endedReason);
        assertEquals("done: step limit 200 reached", ended, "an orderly end is not overwritten by the close");
        assertEquals(200L, (long) Scenes.onEdt(() -> model.snapshot().step()));
        assertEquals(201, Scenes.onEdt(() -> model.trails().points("r1").length / 2), "every snapshot extended the trail");
    }

    @Test
    void aReloadedWorldStartsAfresh() throws Exception {
        ViewModel model = new ViewModel();
        LiveFeed feed = new LiveFeed(model);
        feed.world(Scenes.world());
        feed.snapshot(Scenes.snapshot(1));
        feed.snapshot(Scenes.snapshot(2));
        feed.world(Scenes.world());
        feed.snapshot(Scenes.snapshot(3));
        feed.close();
        assertEquals(3L, (long) Scenes.onEdt(() -> model.snapshot().step()));
        assertEquals(1, Scenes.onEdt(() -> model.trails().points("r1").length / 2), "the trail restarted");
        assertEquals("the connection ended", Scenes.onEdt(model::endedReason));
    }
}
