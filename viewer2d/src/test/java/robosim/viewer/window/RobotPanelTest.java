package robosim.viewer.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.MouseEvent;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.viewer.draw.RenderOptions;
import robosim.viewer.draw.WorldRenderer;

/**
 * The window's readouts, painted off-screen (no display needed): the world point under the mouse,
 * the whole end reason, and the panel of a clicked robot.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class RobotPanelTest {
    /** The fixture world fills a view 800 px wide: 1 px is 5 mm, the key below it. */
    private static final int HEIGHT = 400 + WorldRenderer.keyHeight(Scenes.world(), RenderOptions.of(800).withTrails(true), 800);

    private static ViewerPane pane(ViewModel model) {
        ViewerPane pane = new ViewerPane(model, new ViewState());
        model.world(Scenes.world());
        model.snapshots(List.of(Scenes.snapshot(7)));
        pane.worldView().setSize(800, HEIGHT);
        return pane;
    }

    private static void mouse(WorldView view, int id, int x, int y) {
        view.dispatchEvent(new MouseEvent(view, id, 0, 0, x, y, 1, false, MouseEvent.BUTTON1));
    }

    @Test
    void theCursorReadoutGivesTheWorldPointUnderTheMouse() throws Exception {
        ViewModel model = new ViewModel();
        String[] shown = Scenes.onEdt(() -> {
            ViewerPane pane = pane(model);
            mouse(pane.worldView(), MouseEvent.MOUSE_MOVED, 250, 250);
            String over = pane.statusBar().cursorShown();
            mouse(pane.worldView(), MouseEvent.MOUSE_MOVED, 250, 405);
            return new String[] {over, pane.statusBar().cursorShown()};
        });
        assertEquals("x 1250 mm, y 750 mm", shown[0], "pixel (250, 250) is (1250, 750) mm: y is up");
        assertEquals(" ", shown[1], "over the key, off the world: no readout");
    }

    @Test
    void theStatusLineWrapsSoALongEndReasonShowsWhole() throws Exception {
        ViewModel model = new ViewModel();
        String reason = "error: robot r3 closed its connection at step 5837 while the others waited; "
                + "the run stopped because every robot must answer each step in a lockstep run";
        Object[] seen = Scenes.onEdt(() -> {
            ViewerPane pane = pane(model);
            model.ended(reason);
            pane.screenshot(500, 600);
            pane.screenshot(500, 600);
            return new Object[] {pane.statusBar().shown(), pane.statusBar().lines().getHeight(),
                pane.statusBar().lines().getFontMetrics(pane.statusBar().lines().getFont()).getHeight()};
        });
        assertTrue(((String) seen[0]).endsWith("ended: " + reason), (String) seen[0]);
        assertTrue((int) seen[1] >= 2 * (int) seen[2], "wrapped onto more lines: " + seen[1] + " px high");
    }

    @Test
    void clickingARobotOpensItsPanelAndClickingTheFloorClosesIt() throws Exception {
        ViewModel model = new ViewModel();
        Object[] seen = Scenes.onEdt(() -> {
            ViewerPane pane = pane(model);
            boolean hiddenAtFirst = !pane.robotPanel().isVisible();
            // r1 is at (2700, 1500) mm at step 7: pixel (540, 100)
            mouse(pane.worldView(), MouseEvent.MOUSE_CLICKED, 543, 102);
            String chosen = model.selected();
            boolean visible = pane.robotPanel().isVisible();
            String text = pane.robotPanel().shown();
            BufferedImage shot = pane.screenshot(1100, 700);
            mouse(pane.worldView(), MouseEvent.MOUSE_CLICKED, 100, 300);
            return new Object[] {hiddenAtFirst, chosen, visible, text, shot, model.selected(), pane.robotPanel().isVisible()};
        });
        assertTrue((boolean) seen[0], "no panel before a click");
        assertEquals("r1", seen[1]);
        assertTrue((boolean) seen[2]);
        String text = (String) seen[3];
        assertTrue(text.startsWith("r1: connected, moving freely\n"), text);
        assertTrue(text.contains("true pose: x 2700 mm, y 1500 mm, heading 0.0°"), text);
        assertTrue(text.contains("believed (odometry): x 2700 mm, y 1500 mm, heading 0.0°"), text);
        assertTrue(text.contains("velocity: 0 mm/s, turning 0.0°/s"), text);
        assertTrue(text.contains("sonar (mm): 0:800 1:400"), text);
        assertTrue(count((BufferedImage) seen[4], SensorPlot.SONAR.getRGB()) > 50, "the sonar plot is drawn");
        assertTrue(count((BufferedImage) seen[4], WorldView.SELECTED.getRGB()) > 50, "the chosen robot is ringed");
        assertNull(seen[5], "a click on the floor chooses no robot");
        assertFalse((boolean) seen[6]);
    }

    @Test
    void thePanelShowsTheRobotsStallOdometryAndMessages() throws Exception {
        ViewModel model = new ViewModel();
        RobotView drifted = new RobotView("r1", 2000, 1500, 90, true, true, new int[] {300, 200}, 2030, 1460, 85,
                null, 0, 150, -12.5);
        Snapshot said = new Snapshot(8, 800, List.of(drifted), List.of(), List.of(new Snapshot.Said("r1", "wall ahead")));
        List<String> lines = Scenes.onEdt(() -> {
            pane(model);
            model.snapshots(List.of(said));
            model.select("r1");
            return RobotPanel.lines(model, drifted);
        });
        assertEquals("r1: connected, STALLED (pushing against something)", lines.get(0));
        assertEquals("odometry error: 50 mm, 5.0°", lines.get(3));
        assertEquals("velocity: 150 mm/s, turning -12.5°/s", lines.get(4));
        assertEquals("  step 8: r1 said \"wall ahead\"", lines.get(lines.size() - 1));
    }

    private static int count(BufferedImage image, int rgb) {
        int n = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                n += image.getRGB(x, y) == rgb ? 1 : 0;
            }
        }
        return n;
    }
}
