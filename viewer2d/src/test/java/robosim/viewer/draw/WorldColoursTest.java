package robosim.viewer.draw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.Obstacle;

/**
 * The world's own colours: an obstacle the world file colours is drawn in that colour, one without
 * is drawn as a wall; the gold is marked apart from a plain heat source. A 4000 x 2000 mm world
 * 800 px wide: 5 mm a pixel, y flipped.
 */
class WorldColoursTest {
    private static WorldDescription world(Obstacle... obstacles) {
        return new WorldDescription("colours", 4000, 2000, 100, List.of(obstacles), List.of());
    }

    @Test
    void aRedPolygonIsDrawnRedAndAPlainOneAsAWall() {
        Obstacle red = new Obstacle(new double[] {1000, 500, 1500, 500, 1500, 1000, 1000, 1000}, 300, "red");
        Obstacle plain = new Obstacle(new double[] {2500, 500, 3000, 500, 3000, 1000, 2500, 1000}, 300);
        Obstacle hex = new Obstacle(new double[] {3200, 1200, 3600, 1200, 3600, 1600, 3200, 1600}, 300, "#1e90ff");

        BufferedImage image = new WorldRenderer().render(world(red, plain, hex), null, RenderOptions.of(800));

        assertEquals(new Color(255, 0, 0), Pixels.at(image, 250, 250), "(1250, 750) mm, inside the red polygon");
        assertEquals(WorldRenderer.OBSTACLE, Pixels.at(image, 550, 250), "(2750, 750) mm, the plain one");
        assertEquals(new Color(0x1e, 0x90, 0xff), Pixels.at(image, 680, 120), "(3400, 1400) mm, #1e90ff");
    }

    @Test
    void aColourNoViewerKnowsFallsBackToTheWallsGrey() {
        assertEquals(WorldRenderer.OBSTACLE, WorldRenderer.colourOf(new Obstacle(new double[6], 1, "ultraviolet")));
    }

    @Test
    void theGoldIsMarkedInGoldAndAPlainHeatSourceIsNot() {
        WorldDescription world = new WorldDescription("heat", 4000, 2000, 100, List.of(), List.of(), List.of(
                new WorldDescription.HeatSource(1000, 1500, 40, true), new WorldDescription.HeatSource(3000, 1500, 40)));

        BufferedImage image = new WorldRenderer().render(world, null, RenderOptions.of(800));

        assertEquals(HeatPainter.GOLD, Pixels.at(image, 200, 100), "the gold's marker at (1000, 1500) mm");
        assertTrue(!Pixels.at(image, 600, 100).equals(HeatPainter.GOLD), "the heat source's marker is not gold");
    }

    @Test
    void aMapsForbiddenAreasAreExplainedInTheLegend() {
        WorldDescription.Zone area = new WorldDescription.Zone(true, new double[] {0, 0, 500, 0, 500, 500, 0, 500}, "");
        WorldDescription.Zone line = new WorldDescription.Zone(false, new double[] {0, 1000, 900, 1000}, "");
        WorldDescription map = new WorldDescription("map", 4000, 2000, 100, List.of(), List.of(), List.of(), 0, 0,
                List.of(area));
        WorldDescription both = new WorldDescription("map", 4000, 2000, 100, List.of(), List.of(), List.of(), 0, 0,
                List.of(area, line));

        assertTrue(WorldRenderer.legend(map, RenderOptions.of(800))
                .contains("dashed red: forbidden area (robots' programs keep out; not solid)"));
        assertTrue(WorldRenderer.legend(both, RenderOptions.of(800))
                .contains("dashed red: forbidden area or line (robots' programs keep out; not solid)"));
        assertTrue(WorldRenderer.legend(world(), RenderOptions.of(800)).stream().noneMatch(e -> e.contains("forbidden")));
    }
}
