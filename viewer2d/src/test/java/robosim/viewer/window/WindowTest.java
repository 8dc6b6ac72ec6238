package robosim.viewer.window;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.event.MouseEvent;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.viewer.draw.RenderOptions;
import robosim.viewer.draw.RobotPalette;
import robosim.viewer.draw.WorldRenderer;
import robosim.viewer.view3d.SolidRenderer;

/**
 * The live window, painted off-screen (no display needed): its screenshot shows the world, its
 * drawing equals the PNG images', and its controls change what it shows.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class WindowTest {
    /** A live pane that has been fed the world and snapshots 0 to 7. */
    private static ViewerPane livePane(ViewModel model) {
        ViewerPane pane = new ViewerPane(model, new ViewState());
        model.source("live from test");
        model.world(Scenes.world());
        for (int step = 0; step <= 7; step++) {
            model.snapshots(List.of(Scenes.snapshot(step)));
        }
        return pane;
    }

    private static int count(BufferedImage image, Color colour) {
        int n = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                n += image.getRGB(x, y) == colour.getRGB() ? 1 : 0;
            }
        }
        return n;
    }

    private static int[] pixels(BufferedImage image) {
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    @Test
    void theScreenshotShowsTheWorldTheRobotAndTheStep() throws Exception {
        ViewModel model = new ViewModel();
        BufferedImage shot = Scenes.onEdt(() -> livePane(model).screenshot(900, 600));
        assertTrue(count(shot, WorldRenderer.OBSTACLE) > 1000, "the block is drawn");
        assertTrue(count(shot, WorldRenderer.BACKGROUND) > 50_000, "the floor is drawn");
        assertTrue(count(shot, RobotPalette.colour(0)) > 200, "r1 is drawn in its colour");
        String status = Scenes.onEdt(() -> StatusBar.text(model));
        assertEquals("world fixture · step 7 · t = 0.7 s · 1 robots · live from test", status);
    }

    @Test
    void theViewDrawsThePixelsOfThePngImage() throws Exception {
        ViewModel model = new ViewModel();
        int height = 400 + WorldRenderer.keyHeight(Scenes.world(), RenderOptions.of(800).withTrails(true), 800);
        BufferedImage window = Scenes.onEdt(() -> {
            ViewerPane pane = livePane(model);
            WorldView view = pane.worldView();
            view.setSize(800, height);
            BufferedImage image = new BufferedImage(800, height, BufferedImage.TYPE_INT_RGB);
            Graphics2D g = image.createGraphics();
            view.paint(g);
            g.dispose();
            return image;
        });
        BufferedImage png = new WorldRenderer().render(Scenes.world(), Scenes.snapshot(7),
                RenderOptions.of(800).withTrails(true), model.trails());
        assertArrayEquals(pixels(png), pixels(window), "the window at zoom 1 equals the PNG image, key and all");
    }

    @Test
    void theTogglesChangeWhatIsDrawn() throws Exception {
        ViewModel model = new ViewModel();
        BufferedImage[] shots = Scenes.onEdt(() -> {
            ViewerPane pane = livePane(model);
            BufferedImage before = pane.screenshot(900, 600);
            pane.displayControls().toggle("Sonar").doClick();
            pane.displayControls().toggle("Names").doClick();
            BufferedImage without = pane.screenshot(900, 600);
            pane.displayControls().toggle("3D").doClick();
            BufferedImage solid = pane.screenshot(900, 600);
            return new BufferedImage[] {before, without, solid};
        });
        assertTrue(count(shots[1], new Color(SolidRenderer.SKY.getRGB())) == 0, "2D has no sky");
        assertTrue(!java.util.Arrays.equals(pixels(shots[0]), pixels(shots[1])), "sonar rays and names hidden");
        assertTrue(count(shots[2], new Color(SolidRenderer.SKY.getRGB())) > 10_000, "the 3D view has a sky");
    }

    @Test
    void theChooserFollowsARobotAndADragLetsItGo() throws Exception {
        ViewModel model = new ViewModel();
        ViewState state = new ViewState();
        Scenes.onEdt(() -> {
            ViewerPane pane = new ViewerPane(model, state);
            model.world(Scenes.world());
            model.snapshots(List.of(Scenes.snapshot(7)));
            javax.swing.JComboBox<String> chooser = pane.displayControls().followChooser();
            assertEquals(2, chooser.getItemCount(), "(none) and r1");
            chooser.setSelectedItem("r1");
            assertEquals("r1", state.follow());
            ViewState.Placement p = state.place(Scenes.world(), Scenes.snapshot(7), 800, 400);
            assertEquals(400 - p.view().px(2700), p.originX(), 1e-9, "r1 at x = 2700 is in the centre");
            WorldView view = pane.worldView();
            view.setSize(800, 400);
            view.dispatchEvent(new MouseEvent(view, MouseEvent.MOUSE_PRESSED, 0, 0, 100, 100, 1, false, MouseEvent.BUTTON1));
            view.dispatchEvent(new MouseEvent(view, MouseEvent.MOUSE_DRAGGED, 0, 0, 140, 90, 1, false, MouseEvent.BUTTON1));
            assertEquals(null, state.follow(), "dragging lets the robot go");
            assertEquals(DisplayControls.NOBODY, chooser.getSelectedItem());
            return null;
        });
    }
}
