package robosim.viewer.draw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Snapshot.RobotView;

/**
 * A robot's camera in the fixture world (1 px is 5 mm, y flipped): the robot stands at
 * (3000, 600) mm, pixel (600, 280), facing +x; the edges of its field of view are dashed.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class CameraDrawingTest {
    private final WorldRenderer renderer = new WorldRenderer();

    private BufferedImage render(double[] camera) {
        RobotView r = new RobotView("r1", 3000, 600, 0, false, true, new int[0], 3000, 600, 0, new int[0], 1, 0, 0,
                camera);
        RenderOptions options = new RenderOptions(Fixtures.WIDTH_PX, false, false).withLaser(false).withOdometry(false);
        return renderer.render(Fixtures.world(), Fixtures.snapshot(1, r), options);
    }

    /** @return how many of 40 points from 500 to 950 mm along a bearing (degrees) are drawn on */
    private static int drawnAlong(BufferedImage image, double bearing) {
        int drawn = 0;
        for (int k = 0; k < 40; k++) {
            double d = 500 + k * 450 / 40.0;
            int px = (int) Math.round((3000 + d * Math.cos(Math.toRadians(bearing))) / 5);
            int py = (int) Math.round(400 - (600 + d * Math.sin(Math.toRadians(bearing))) / 5);
            if (!WorldRenderer.BACKGROUND.equals(Pixels.at(image, px, py))) {
                drawn++;
            }
        }
        return drawn;
    }

    @Test
    void theFieldOfViewsEdgesAreDrawnAlongTheHeadingMinusThePan() {
        BufferedImage ahead = render(new double[] {0, 45});
        assertTrue(drawnAlong(ahead, 22.5) > 15, "left edge, dashed");
        assertTrue(drawnAlong(ahead, -22.5) > 15, "right edge");
        assertEquals(0, drawnAlong(ahead, 0), "the view between the edges stays clear");
        BufferedImage left = render(new double[] {-90, 20});
        assertTrue(drawnAlong(left, 100) > 15, "panned 90° left: edges at 80° and 100°");
        assertTrue(drawnAlong(left, 80) > 15);
        assertEquals(0, drawnAlong(left, 22.5));
    }

    @Test
    void aRobotWithoutACameraHasNoEdges() {
        BufferedImage none = render(null);
        assertEquals(0, drawnAlong(none, 22.5));
        assertEquals(0, drawnAlong(none, -22.5));
    }
}
