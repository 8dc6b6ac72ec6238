package robosim.viewer.draw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static robosim.viewer.draw.Pixels.at;

import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.WorldDescription;

/** A map's world, which need not start at (0, 0), and its forbidden zones. */
class MapWorldDrawingTest {
    /** 10 m x 8 m from (-4000, -3000): drawn 1000 px wide, 10 mm a pixel. */
    private static WorldDescription map(List<WorldDescription.Zone> zones) {
        return new WorldDescription("lab", 10000, 8000, 100,
                List.of(new WorldDescription.Obstacle(new double[] {-3500, -2500, -3000, -2500, -3000, -2000, -3500, -2000},
                        500)),
                List.of(), List.of(), -4000, -3000, zones);
    }

    @Test
    void theWorldsCornersMapToTheImagesCorners() {
        ViewTransform view = ViewTransform.fit(map(List.of()), 1000);
        assertEquals(List.of(0.0, 0.0, 1000.0, 800.0),
                List.of(view.px(-4000), view.py(5000), view.px(6000), view.py(-3000)));
    }

    @Test
    void anObstacleBelowAndLeftOfTheOriginIsDrawnWhereItLies() {
        BufferedImage image = new WorldRenderer().render(map(List.of()), null, RenderOptions.of(1000));
        // (-3250, -2250) mm is pixel (75, 725)
        assertEquals(WorldRenderer.OBSTACLE, at(image, 75, 725));
        assertEquals(WorldRenderer.BACKGROUND, at(image, 75, 650));
    }

    @Test
    void aForbiddenAreaIsOutlinedNotFilled() {
        WorldDescription.Zone area = new WorldDescription.Zone(true,
                new double[] {0, 0, 2000, 0, 2000, 2000, 0, 2000}, "keep out");
        BufferedImage image = new WorldRenderer().render(map(List.of(area)), null, RenderOptions.of(1000));
        // its bottom edge, y = 0 mm, is pixel row 500; x = 0 mm is column 400, the dash starts there
        assertEquals(WorldRenderer.FORBIDDEN, at(image, 402, 500));
        assertEquals(WorldRenderer.BACKGROUND, at(image, 500, 400));
    }
}
