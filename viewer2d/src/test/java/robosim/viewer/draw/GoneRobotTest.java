package robosim.viewer.draw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Snapshot;

/**
 * A robot gone from the run (removed, left, dropped) is drawn as a dashed outline where it stopped,
 * not in the grey of a robot whose program has not connected yet. r1 at (3000, 600) mm has its
 * centre at pixel (600, 280); 150 mm behind its centre, pixel (570, 280), lies inside its body.
 */
class GoneRobotTest {
    private final WorldRenderer renderer = new WorldRenderer();

    private static Snapshot notConnected(long step, Snapshot.Event... events) {
        return new Snapshot(step, step * 100, List.of(Fixtures.robot(3000, 600, 0, false, false)), List.of(),
                List.of(), List.of(events));
    }

    private BufferedImage render(Snapshot s) {
        return renderer.render(Fixtures.world(), s, RenderOptions.of(Fixtures.WIDTH_PX).withSonar(false));
    }

    @Test
    void aRobotNotConnectedYetIsFilledGrey() {
        assertEquals(RobotPalette.DISCONNECTED, Pixels.at(render(notConnected(5)), 570, 280));
    }

    @Test
    void aRemovedRobotIsAnOutlineNotFilledGrey() {
        Snapshot removed = notConnected(5, new Snapshot.Event("r1", "dropped", 5, "removed by control client panel"));

        BufferedImage image = render(removed);

        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(image, 570, 280), "the floor shows through its body");
        // its rear edge, 200 mm behind its centre, is pixel column 560: dashed grey along it somewhere
        int grey = 0;
        for (int y = 250; y <= 310; y++) {
            if (Pixels.at(image, 560, y).equals(WorldRenderer.GONE_OUTLINE)) {
                grey++;
            }
        }
        assertTrue(grey > 5 && grey < 55, "a dashed edge, not a solid one: " + grey + " grey pixels of 61");
    }

    @Test
    void aFollowerKeepsARobotGoneAfterTheStepItWent() {
        Departures departures = new Departures();
        List<Snapshot> run = List.of(
                new Snapshot(1, 100, List.of(Fixtures.robot(3000, 600, 0, false, true))),
                notConnected(2, new Snapshot.Event("r1", "left", 2, "done")),
                notConnected(3));
        for (Snapshot s : run) {
            departures.add(s);
        }

        Snapshot shown = departures.over(run.get(2));

        assertTrue(departures.gone("r1"));
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(render(shown), 570, 280));
        assertEquals(RobotPalette.DISCONNECTED, Pixels.at(render(run.get(2)), 570, 280),
                "without the follower, step 3 alone cannot tell");
    }

    @Test
    void aRobotThatJoinsAgainIsNoLongerGone() {
        Departures departures = new Departures();
        departures.add(notConnected(2, new Snapshot.Event("r1", "dropped", 2, "removed")));
        departures.add(new Snapshot(3, 300, List.of(Fixtures.robot(1000, 1500, 0, false, true)), List.of(), List.of(),
                List.of(new Snapshot.Event("r1", "rejoined", 3, ""))));

        assertFalse(departures.gone("r1"));
    }

    @Test
    void aRobotSeenConnectedThenNotIsGoneEvenWithoutAnEvent() {
        Departures departures = new Departures();
        departures.add(new Snapshot(1, 100, List.of(Fixtures.robot(3000, 600, 0, false, true))));
        departures.add(notConnected(2));

        assertTrue(Departures.gone(departures.over(notConnected(2)), Fixtures.robot(3000, 600, 0, false, false)));
    }
}
