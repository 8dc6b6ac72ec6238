package robosim.viewer.draw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Figure;
import robosim.protocol.Snapshot;

/**
 * The robots' drawings in the fixture world (1 px is 5 mm, y flipped): a cell from (2000, 1500) to
 * (2500, 1750) mm covers pixels 400 to 500 across and 50 to 100 down; its middle is (450, 75).
 */
class DrawingPainterTest {
    private static final Figure CELL = new Figure(Figure.CELLS, "", new double[] {2000, 1500, 2500, 1750});
    private final WorldRenderer renderer = new WorldRenderer();

    private static Snapshot drawn(long step, Figure... figures) {
        return Fixtures.snapshot(step, Fixtures.robotAtRest())
                .withDrawings(List.of(new Snapshot.Drawing("r1", "map", List.of(figures))));
    }

    private BufferedImage render(Snapshot snapshot, boolean drawings) {
        return renderer.render(Fixtures.world(), snapshot, RenderOptions.of(Fixtures.WIDTH_PX).withDrawings(drawings));
    }

    /** @return the colour over the floor at the painter's fill opacity */
    private static Color overFloor(Color c) {
        Color bg = WorldRenderer.BACKGROUND;
        int a = DrawingPainter.FILL_ALPHA;
        return new Color((c.getRed() * a + bg.getRed() * (255 - a)) / 255,
                (c.getGreen() * a + bg.getGreen() * (255 - a)) / 255, (c.getBlue() * a + bg.getBlue() * (255 - a)) / 255);
    }

    private static void assertNear(Color expected, Color actual) {
        assertTrue(Math.abs(expected.getRed() - actual.getRed()) <= 2
                && Math.abs(expected.getGreen() - actual.getGreen()) <= 2
                && Math.abs(expected.getBlue() - actual.getBlue()) <= 2, "expected about " + expected + ", got " + actual);
    }

    @Test
    void aCellIsDrawnTranslucentInTheRobotsColourWhenTheOptionIsOn() {
        assertNear(overFloor(RobotPalette.colour(0)), Pixels.at(render(drawn(5, CELL), true), 450, 75));
    }

    @Test
    void drawingsAreNotDrawnWhenTheOptionIsOff() {
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(render(drawn(5, CELL), false), 450, 75));
    }

    @Test
    void aFigureThatNamesAColourIsDrawnInIt() {
        Figure red = new Figure(Figure.CELLS, "red", new double[] {2000, 1500, 2500, 1750});
        assertNear(overFloor(Color.RED), Pixels.at(render(drawn(5, red), true), 450, 75));
    }

    @Test
    void aPolygonIsFilledAndALineAndDotsAreDrawn() {
        Figure polygon = new Figure(Figure.POLYGON, "", new double[] {2000, 1500, 2500, 1500, 2500, 1750});
        Figure line = new Figure(Figure.LINE, "", new double[] {250, 1000, 750, 1000});
        Figure dot = new Figure(Figure.DOTS, "", new double[] {3500, 1500});
        BufferedImage image = render(drawn(5, polygon, line, dot), true);
        assertNear(overFloor(RobotPalette.colour(0)), Pixels.at(image, 490, 95));
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(image, 410, 55), "outside the triangle");
        assertTrue(!WorldRenderer.BACKGROUND.equals(Pixels.at(image, 100, 200)), "on the line");
        assertTrue(!WorldRenderer.BACKGROUND.equals(Pixels.at(image, 700, 100)), "on the dot");
    }

    @Test
    void followingARunKeepsADrawingUntilItIsCleared() throws Exception {
        List<BufferedImage> images = new ArrayList<>();
        RenderedImages out = new RenderedImages(
                SnapshotPainter.flat(renderer, RenderOptions.of(Fixtures.WIDTH_PX).withDrawings(true)),
                (step, image) -> images.add(image), 1, false);
        out.world(Fixtures.world());
        out.snapshot(drawn(1, CELL));
        out.snapshot(Fixtures.snapshot(2, Fixtures.robotAtRest()));
        out.snapshot(drawn(3));
        assertNear(overFloor(RobotPalette.colour(0)), Pixels.at(images.get(1), 450, 75));
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(images.get(2), 450, 75), "cleared at step 3");
    }

    @Test
    void theLegendSaysWhatTheTranslucentFiguresAreOnlyWhenTheyAreShown() {
        RenderOptions plain = RenderOptions.of(800);
        assertTrue(WorldRenderer.legend(Fixtures.world(), plain.withDrawings(true))
                .contains("translucent: what a robot drew"));
        assertEquals(WorldRenderer.legend(Fixtures.world(), plain).size() + 1,
                WorldRenderer.legend(Fixtures.world(), plain.withDrawings(true)).size());
        assertTrue(renderer.render(Fixtures.world(), null, plain.withDrawings(true)).getHeight()
                >= renderer.render(Fixtures.world(), null, plain).getHeight());
    }

    @Test
    void aWorldForgetsTheDrawings() {
        Drawings drawings = new Drawings();
        drawings.add(drawn(1, CELL));
        assertEquals(1, drawings.all().size());
        drawings.clear();
        Snapshot plain = Fixtures.snapshot(2, Fixtures.robotAtRest());
        assertTrue(drawings.over(plain) == plain, "nothing to carry: the snapshot itself");
    }
}
