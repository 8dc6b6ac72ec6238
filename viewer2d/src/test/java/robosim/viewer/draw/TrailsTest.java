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
}
