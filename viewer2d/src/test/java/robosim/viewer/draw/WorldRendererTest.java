package robosim.viewer.draw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

@Timeout(value = 30, unit = TimeUnit.SECONDS)
class WorldRendererTest {
    private final WorldRenderer renderer = new WorldRenderer();

    private BufferedImage render(Snapshot snapshot, boolean sonar, boolean names) {
        return renderer.render(Fixtures.world(), snapshot, new RenderOptions(Fixtures.WIDTH_PX, sonar, names));
    }

    private static Color at(BufferedImage image, int x, int y) {
        return new Color(image.getRGB(x, y));
    }

    @Test
    void imageIsAsWideAsAskedAndAsHighAsTheWorldsAspectPlusTheKey() {
        BufferedImage image = render(Fixtures.snapshot(1, Fixtures.robotAtRest()), true, true);
        assertEquals(BufferedImage.TYPE_INT_RGB, image.getType());
        assertEquals(800, image.getWidth());
        int key = WorldRenderer.keyHeight(Fixtures.world(), new RenderOptions(800, true, true), 800);
        assertTrue(key >= 2 * 15, "a row for the step and scale bar, and the legend's: " + key);
        assertEquals(400 + key, image.getHeight());

        WorldDescription tall = new WorldDescription("tall", 1000, 3000, 100, List.of(), List.of());
        BufferedImage portrait = renderer.render(tall, null, RenderOptions.of(300));
        assertEquals(300, portrait.getWidth());
        assertEquals(900 + WorldRenderer.keyHeight(tall, RenderOptions.of(300), 300), portrait.getHeight());
    }

    @Test
    void obstacleIsDarkAndFreeSpaceLightWithYUp() {
        BufferedImage image = render(Fixtures.snapshot(1, Fixtures.robotAtRest()), false, false);
        // Obstacle centre (1250, 750) mm is pixel (250, 250): y is flipped, so it is in the lower half.
        assertEquals(WorldRenderer.OBSTACLE, at(image, 250, 250));
        // Its mirror across the middle, (1250, 1250) mm, is free.
        assertEquals(WorldRenderer.BACKGROUND, at(image, 250, 150));
        assertEquals(WorldRenderer.BACKGROUND, at(image, 600, 100));
    }

    @Test
    void borderIsDrawnAtTheImageEdge() {
        BufferedImage image = render(null, false, false);
        assertEquals(WorldRenderer.BORDER, at(image, 0, 200));
        assertEquals(WorldRenderer.BORDER, at(image, 799, 200));
        assertEquals(WorldRenderer.BORDER, at(image, 400, 399));
    }

    @Test
    void robotBodyIsFilledInItsColour() {
        BufferedImage image = render(Fixtures.snapshot(1, Fixtures.robotAtRest()), false, false);
        // (2900, 700) mm lies inside the body, away from the outline and the heading line.
        assertEquals(RobotPalette.colour(0), at(image, 580, 260));
        // Just outside the body's rear edge at x = 2800 mm (pixel 560).
        assertEquals(WorldRenderer.BACKGROUND, at(image, 555, 260));
    }

    @Test
    void headingLineFollowsTheHeadingCounterClockwiseInDegrees() {
        // Turned to 90 degrees the robot faces +y, which is up in the image: the heading line runs
        // from the centre (600, 280) to the nose (600, 240).
        BufferedImage north = render(Fixtures.snapshot(1, Fixtures.robot(3000, 600, 90, false, true)), false, false);
        BufferedImage east = render(Fixtures.snapshot(1, Fixtures.robotAtRest()), false, false);
        assertTrue(brightness(at(north, 600, 260)) < 80, "heading line above the centre when facing +y");
        assertEquals(RobotPalette.colour(0), at(east, 600, 260));
    }

    @Test
    void stalledRobotIsOutlinedInRed() {
        BufferedImage free = render(Fixtures.snapshot(1, Fixtures.robotAtRest()), false, false);
        BufferedImage stalled = render(Fixtures.snapshot(1, Fixtures.robot(3000, 600, 0, true, true)), false, false);
        assertEquals(0, redPixels(free, 550, 230, 650, 330));
        assertTrue(redPixels(stalled, 550, 230, 650, 330) > 100);
    }

    @Test
    void disconnectedRobotIsGreyedOut() {
        BufferedImage image = render(Fixtures.snapshot(1, Fixtures.robot(3000, 600, 0, false, false)), false, false);
        assertEquals(RobotPalette.DISCONNECTED, at(image, 580, 260));
    }

    @Test
    void sonarRaysAppearOnlyWhenAsked() {
        Snapshot snapshot = Fixtures.snapshot(1, Fixtures.robotAtRest());
        BufferedImage on = render(snapshot, true, false);
        BufferedImage off = render(snapshot, false, false);
        // Sonar 0 runs 500 mm forward from the nose (3200, 600): pixels (640..740, 280).
        assertNotEquals(at(off, 700, 280), at(on, 700, 280));
        assertEquals(WorldRenderer.BACKGROUND, at(off, 700, 280));
        // Sonar 1 runs 300 mm left (+y, up) from (3000, 790): pixels (600, 182..222).
        assertNotEquals(at(off, 600, 200), at(on, 600, 200));
        // Beyond the echo at 500 mm nothing is drawn.
        assertEquals(WorldRenderer.BACKGROUND, at(on, 760, 280));
    }

    @Test
    void namesAppearOnlyWhenAsked() {
        Snapshot snapshot = Fixtures.snapshot(1, Fixtures.robotAtRest());
        BufferedImage on = render(snapshot, false, true);
        BufferedImage off = render(snapshot, false, false);
        assertTrue(differingPixels(on, off, 630, 200, 720, 250) > 0, "the name is written up and right");
    }

    @Test
    void captionShowsStepAndSimulatedTime() {
        assertEquals("step 120  t=12.0 s", WorldRenderer.caption(new Snapshot(120, 12_000, List.of())));
        BufferedImage captioned = render(Fixtures.snapshot(120), false, false);
        BufferedImage bare = render(null, false, false);
        assertEquals(0, differingPixels(captioned, bare, 0, 0, 800, 400), "the caption is not on the world");
        assertTrue(differingPixels(captioned, bare, 0, 400, 200, 420) > 0, "it is in the key's first row");
    }

    @Test
    void theKeyHasAScaleBarOfARoundLength() {
        // 1 px is 5 mm; a quarter of 800 px is 1000 mm: the bar is 1 m, 200 px, ending 8 px from the right.
        assertEquals(1000, ScaleBar.barLength(0.2, 800));
        assertEquals("1 m", ScaleBar.label(1000));
        assertEquals("500 mm", ScaleBar.label(500));
        assertEquals("2 m", ScaleBar.label(ScaleBar.roundLength(4999)));
        BufferedImage image = render(null, false, false);
        int barRow = -1;
        for (int y = 400; y < 420 && barRow < 0; y++) {
            if (at(image, 700, y).equals(new Color(20, 20, 20))) {
                barRow = y;
            }
        }
        assertTrue(barRow > 0, "a dark bar in the key's first row at x = 700");
        assertEquals(new Color(20, 20, 20), at(image, 600, barRow), "it reaches 200 px left of its end");
        assertEquals(Color.WHITE, at(image, 580, barRow), "and no further");
    }

    @Test
    void theLegendNamesEachRobotAndWhatTheStatesAndMarksMean() {
        assertEquals(List.of("r1", "front (heading)", "grey: not connected yet",
                        "dashed grey: gone (left, dropped or removed)", "red edge: stalled",
                        "dashed: where it believes it is (odometry)", "sonar rays", "laser scan", "wall"),
                WorldRenderer.legend(Fixtures.world(), new RenderOptions(800, true, true)));
        WorldDescription heat = Fixtures.world(Fixtures.params(150, 0, 0, 8000),
                List.of(new WorldDescription.HeatSource(500, 500, 40)));
        assertEquals(List.of("r1", "front (heading)", "grey: not connected yet",
                        "dashed grey: gone (left, dropped or removed)", "red edge: stalled", "laser scan",
                        "trail", "heat source", "wall", "grid: 500 mm squares"),
                WorldRenderer.legend(heat, new RenderOptions(800, false, false).withOdometry(false).withTrails(true)
                        .withGrid(true)));
    }

    @Test
    void theLegendSaysGoldOnlyForTheGold() {
        WorldDescription gold = Fixtures.world(Fixtures.params(),
                List.of(new WorldDescription.HeatSource(500, 500, 40, true)));
        WorldDescription both = Fixtures.world(Fixtures.params(),
                List.of(new WorldDescription.HeatSource(500, 500, 40, true), new WorldDescription.HeatSource(3500, 1500, 9)));
        RenderOptions plain = new RenderOptions(800, false, false).withOdometry(false);

        List<String> goldOnly = WorldRenderer.legend(gold, plain);
        assertTrue(goldOnly.contains("gold (it glows with heat)") && !goldOnly.contains("heat source"), goldOnly.toString());
        List<String> mixed = WorldRenderer.legend(both, plain);
        assertTrue(mixed.contains("gold (it glows with heat)") && mixed.contains("heat source"), mixed.toString());
    }

    @Test
    void theLegendShowsEachRobotsColourAndTheGreyOfARobotNotYetConnected() {
        BufferedImage image = render(Fixtures.snapshot(1), false, false);
        assertTrue(count(image, RobotPalette.colour(0), 400) > 20, "r1's colour in the legend");
        assertTrue(count(image, RobotPalette.DISCONNECTED, 400) > 20, "the grey of a robot not connected yet");
        assertTrue(count(image, RobotPalette.STALLED, 400) > 10, "the red edge of a stalled robot");
        assertTrue(count(image, WorldRenderer.OBSTACLE, 400) > 20, "a wall");
    }

    @Test
    void theGridIsDrawnOnlyWhenAsked() {
        RenderOptions plain = new RenderOptions(800, false, false);
        BufferedImage without = renderer.render(Fixtures.world(), null, plain);
        BufferedImage with = renderer.render(Fixtures.world(), null, plain.withGrid(true));
        // 4000 mm wide: 500 mm squares; the line x = 2000 mm is pixel column 400, free space at y = 100.
        assertEquals(WorldRenderer.BACKGROUND, at(without, 400, 100));
        assertNotEquals(WorldRenderer.BACKGROUND, at(with, 400, 100));
        assertEquals(WorldRenderer.BACKGROUND, at(with, 450, 150), "between the lines");
    }

    @Test
    void aNameNearTheTopEdgeIsWrittenBelowTheRobotNotCutOff() {
        Snapshot top = Fixtures.snapshot(1, Fixtures.robot(3000, 1950, 0, false, true));
        BufferedImage on = render(top, false, true);
        BufferedImage off = render(top, false, false);
        // centre at pixel row 10: the name goes under the body (rows 30 to 60)
        assertTrue(differingPixels(on, off, 620, 30, 720, 60) > 0, "the name under the robot");
    }

    @Test
    void theHeadingMarkIsATriangleAtTheNose() {
        BufferedImage east = render(Fixtures.snapshot(1, Fixtures.robotAtRest()), false, false);
        // Nose at pixel (640, 280); the mark reaches 24 px back and 17 px to each side.
        assertTrue(brightness(at(east, 632, 284)) < 80, "dark beside the heading line, inside the mark");
        assertEquals(RobotPalette.colour(0), at(east, 610, 284), "the body's colour behind the mark");
    }

    private static int count(BufferedImage image, Color colour, int fromRow) {
        int n = 0;
        for (int y = fromRow; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                n += image.getRGB(x, y) == colour.getRGB() ? 1 : 0;
            }
        }
        return n;
    }

    @Test
    void robotMissingFromTheWorldIsStillDrawn() {
        Snapshot snapshot = Fixtures.snapshot(1, new Snapshot.RobotView("stranger", 3000, 600, 0, false, true, null));
        BufferedImage image = render(snapshot, true, true);
        assertEquals(RobotPalette.colour(1), at(image, 580, 260));
    }

    @Test
    void worldWithoutAreaIsRejectedNamingTheWorld() {
        WorldDescription flat = new WorldDescription("flat", 4000, 0, 100, List.of(), List.of());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> renderer.render(flat, null, RenderOptions.of(100)));
        assertEquals("world 'flat' has height 0.0 mm: height must be greater than 0 and finite", e.getMessage());
    }

    @Test
    void widthOutOfRangeIsRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> RenderOptions.of(0));
        assertEquals("0 was supplied for width: width must be from 1 to 8192 pixels", e.getMessage());
    }

    private static int brightness(Color c) {
        return (c.getRed() + c.getGreen() + c.getBlue()) / 3;
    }

    private static int redPixels(BufferedImage image, int x0, int y0, int x1, int y1) {
        int n = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                Color c = at(image, x, y);
                if (c.getRed() > 180 && c.getGreen() < 80 && c.getBlue() < 80) {
                    n++;
                }
            }
        }
        return n;
    }

    private static int differingPixels(BufferedImage a, BufferedImage b, int x0, int y0, int x1, int y1) {
        int n = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                if (a.getRGB(x, y) != b.getRGB(x, y)) {
                    n++;
                }
            }
        }
        return n;
    }
}
