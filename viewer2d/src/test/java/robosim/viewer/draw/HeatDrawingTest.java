package robosim.viewer.draw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.HeatSource;

/**
 * Heat sources in the fixture world (1 px is 5 mm, y flipped): a source at (1000, 1500) mm is
 * pixel (200, 100), one at (3000, 1500) mm pixel (600, 100); their glows reach 200 px.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class HeatDrawingTest {
    private final WorldRenderer renderer = new WorldRenderer();

    private BufferedImage render(HeatSource... heat) {
        WorldDescription world = Fixtures.world(Fixtures.params(), List.of(heat));
        return renderer.render(world, null, RenderOptions.of(Fixtures.WIDTH_PX));
    }

    @Test
    void glowIsWarmerNearTheSourceThanFarAway() {
        BufferedImage image = render(new HeatSource(1000, 1500, 40));
        int near = Pixels.warmth(image, 215, 100);
        int middle = Pixels.warmth(image, 300, 100);
        int far = Pixels.warmth(image, 380, 100);
        assertTrue(near > middle && middle > far, near + " > " + middle + " > " + far);
        assertTrue(near > 100, "near the source the glow is clearly warm: " + near);
        // Past the glow's 1000 mm radius the floor is untouched.
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(image, 420, 100));
    }

    @Test
    void strongerSourceGlowsMoreOpaquely() {
        BufferedImage image = render(new HeatSource(1000, 1500, 40), new HeatSource(3000, 1500, 10));
        for (int dx : new int[] {10, 50, 100}) {
            int strong = Pixels.warmth(image, 200 + dx, 100);
            int weak = Pixels.warmth(image, 600 + dx, 100);
            assertTrue(strong > weak, "at " + dx + " px: " + strong + " > " + weak);
        }
    }

    @Test
    void markerIsTheSameSizeWhateverTheIntensity() {
        BufferedImage image = render(new HeatSource(1000, 1500, 40), new HeatSource(3000, 1500, 10));
        // Within 2 px of the centre both markers cover the glow alike.
        for (int dy = -2; dy <= 2; dy++) {
            for (int dx = -2; dx <= 2; dx++) {
                if (dx * dx + dy * dy > 4) {
                    continue;
                }
                assertEquals(Pixels.at(image, 200 + dx, 100 + dy), Pixels.at(image, 600 + dx, 100 + dy),
                        "offset " + dx + ", " + dy);
            }
        }
        // 6 px out neither marker reaches: the glows beneath show, and they differ.
        assertNotEquals(Pixels.at(image, 206, 100), Pixels.at(image, 606, 100));
    }

    @Test
    void glowStaysUnderObstacles() {
        // A source on the square obstacle's top edge, (1250, 1000) mm: the obstacle stays its colour.
        BufferedImage image = render(new HeatSource(1250, 1000, 40));
        assertEquals(WorldRenderer.OBSTACLE, Pixels.at(image, 250, 230));
        assertTrue(Pixels.warmth(image, 250, 185) > 100);
    }

    @Test
    void alphaFollowsTheShareOfTheStrongestWithAFloor() {
        assertEquals(HeatPainter.MAX_ALPHA, HeatPainter.alpha(40, 40));
        assertEquals(Math.round(HeatPainter.MAX_ALPHA * 0.5), HeatPainter.alpha(20, 40));
        assertEquals(Math.round(HeatPainter.MAX_ALPHA * HeatPainter.MIN_SHARE), HeatPainter.alpha(0.001, 40));
    }

    @Test
    void brokenSourcesAreSkipped() {
        BufferedImage none = render();
        BufferedImage broken = render(new HeatSource(Double.NaN, 1500, 40), new HeatSource(1000, 1500, 0),
                new HeatSource(1000, 1500, Double.POSITIVE_INFINITY));
        assertEquals(0, Pixels.differing(none, broken, 0, 0, 800, 400), "the world is drawn alike");
    }
}
