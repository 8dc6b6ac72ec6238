package robosim.viewer.draw;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Each robot's path: spaced points, bounded memory, drawn in its colour. */
class TrailsTest {
    @Test
    void aPointIsKeptEachTimeTheRobotHasMovedTheSpacing() {
        Trails trails = new Trails();
        for (int step = 0; step <= 10; step++) {
            trails.add(Fixtures.snapshot(step, Fixtures.robot(1000 + 7 * step, 1500, 0, false, true)));
        }
        assertEquals(List.of("r1"), trails.robots());
        assertArrayEquals(new double[] {1000, 1500, 1021, 1500, 1042, 1500, 1063, 1500}, trails.points("r1"));
        assertEquals(0, trails.points("nobody").length);
        trails.clear();
        assertEquals(List.of(), trails.robots());
    }

    @Test
    void aLongPathIsThinnedSoMemoryStaysBounded() {
        Trails trails = new Trails();
        for (int i = 0; i < 3 * Trails.MAX_POINTS; i++) {
            trails.add(Fixtures.snapshot(i, Fixtures.robot(i * Trails.SPACING_MM % 4000, 1000 + i / 200, 0, false, true)));
        }
        int points = trails.points("r1").length / 2;
        assertTrue(points <= Trails.MAX_POINTS && points > Trails.MAX_POINTS / 4, points + " points");
    }

    @Test
    void theRendererDrawsTrailsOnlyWhenAskedAndGiven() {
        Trails trails = new Trails();
        for (int step = 0; step <= 20; step++) {
            trails.add(Fixtures.snapshot(step, Fixtures.robot(200 + 100 * step, 1500, 0, false, true)));
        }
        WorldRenderer renderer = new WorldRenderer();
        RenderOptions options = new RenderOptions(800, false, false, false, false).withCaption(false);
        BufferedImage without = renderer.render(Fixtures.world(), Fixtures.snapshot(20, Fixtures.robotAtRest()), options, trails);
        BufferedImage with = renderer.render(Fixtures.world(), Fixtures.snapshot(20, Fixtures.robotAtRest()),
                options.withTrails(true), trails);
        // the path runs along y = 1500 mm, pixel row 100, from x = 200 mm (pixel 40)
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(without, 100, 100));
        assertTrue(Pixels.at(with, 100, 100).getBlue() > Pixels.at(with, 100, 100).getRed() + 40,
                "a blue trail where r1 passed: " + Pixels.at(with, 100, 100));
    }

    @Test
    void aTeleportStartsANewPieceAndNoLineIsDrawnAcrossIt() {
        Trails trails = new Trails();
        for (int step = 0; step <= 5; step++) {
            trails.add(Fixtures.snapshot(step, Fixtures.robot(200 + 100 * step, 1500, 0, false, true)));
        }
        // moved by a control client: 2300 mm in one 100 ms step
        for (int step = 6; step <= 10; step++) {
            trails.add(Fixtures.snapshot(step, Fixtures.robot(3000 + 100 * (step - 6), 1500, 0, false, true)));
        }
        assertEquals(2, trails.pieces("r1"));

        BufferedImage image = new WorldRenderer().render(Fixtures.world(), Fixtures.snapshot(10, Fixtures.robotAtRest()),
                new RenderOptions(800, false, false, false, false).withCaption(false).withTrails(true), trails);
        // y = 1500 mm is pixel row 100: the trail at x = 400 mm (pixel 80), none at 2000 mm (pixel 400)
        assertTrue(Pixels.at(image, 80, 100).getBlue() > Pixels.at(image, 80, 100).getRed() + 40, "the first piece");
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(image, 400, 100), "nothing across the jump");
    }

    @Test
    void drivingFastIsNotAJumpButJoiningAgainIs() {
        Trails trails = new Trails();
        // 2000 mm/s, a Pioneer's top speed: 200 mm a step
        for (int step = 0; step <= 5; step++) {
            trails.add(Fixtures.snapshot(step, Fixtures.robot(200 + 200 * step, 1500, 0, false, true)));
        }
        assertEquals(1, trails.pieces("r1"));
        trails.add(new robosim.protocol.Snapshot(6, 600, List.of(Fixtures.robot(1300, 1500, 0, false, true)), List.of(),
                List.of(), List.of(new robosim.protocol.Snapshot.Event("r1", "rejoined", 6, ""))));
        trails.add(Fixtures.snapshot(7, Fixtures.robot(1400, 1500, 0, false, true)));
        assertEquals(2, trails.pieces("r1"));
    }
}
