package robosim.viewer.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.viewer.draw.ViewTransform;

/** The window's zoom, pan, follow and camera arithmetic, without Swing. */
class ViewStateTest {
    private final WorldDescription world = Scenes.world();
    private final ViewState state = new ViewState();

    /** The world x under a panel pixel. */
    private double worldX(ViewState.Placement p, double px) {
        return (px - p.originX()) / p.view().scale();
    }

    private double worldY(ViewState.Placement p, double py) {
        return world.height() - (py - p.originY()) / p.view().scale();
    }

    @Test
    void atZoomOneThePanelIsPlacedExactlyAsAPngOfItsWidth() {
        ViewState.Placement p = state.place(world, null, 800, 400);
        assertEquals(ViewTransform.fit(world, 800), p.view());
        assertEquals(0, p.originX());
        assertEquals(0, p.originY());
    }

    @Test
    void aWiderPanelCentresTheFittedWorld() {
        ViewState.Placement p = state.place(world, null, 900, 400);
        assertEquals(ViewTransform.fit(world, 800), p.view());
        assertEquals(50, p.originX());
        assertEquals(0, p.originY());
    }

    @Test
    void theWheelZoomsAboutThePointer() {
        ViewState.Placement before = state.place(world, null, 800, 400);
        double x = worldX(before, 200);
        double y = worldY(before, 100);
        state.zoomAbout(2, 200, 100, world, null, 800, 400);
        ViewState.Placement after = state.place(world, null, 800, 400);
        assertEquals(2, state.zoom());
        assertEquals(2 * before.view().scale(), after.view().scale(), 1e-12);
        assertEquals(x, worldX(after, 200), 1e-6, "the world point under the pointer stays under it");
        assertEquals(y, worldY(after, 100), 1e-6);
    }

    @Test
    void aDragPansAndStopsFollowing() {
        state.setFollow("r1");
        state.drag(30, -20);
        assertNull(state.follow());
        ViewState.Placement p = state.place(world, null, 800, 400);
        assertEquals(30, p.originX());
        assertEquals(-20, p.originY());
        state.fit();
        assertEquals(0, state.place(world, null, 800, 400).originX());
    }

    @Test
    void followingKeepsTheRobotInTheCentre() {
        state.setFollow("r1");
        state.zoomAbout(4, 0, 0, world, null, 800, 400);
        Snapshot snapshot = Scenes.snapshot(5);
        ViewState.Placement p = state.place(world, snapshot, 800, 400);
        assertEquals(2500, worldX(p, 400), 1e-6);
        assertEquals(1500, worldY(p, 200), 1e-6);
    }

    @Test
    void in3dADragTurnsTheCameraAndTheWheelZoomsIt() {
        state.setThreeD(true);
        double azimuth = state.camera().azimuth();
        double elevation = state.camera().elevation();
        state.drag(20, 10);
        assertEquals(azimuth - 10, state.camera().azimuth(), 1e-9);
        assertEquals(elevation + 5, state.camera().elevation(), 1e-9);
        state.zoomAbout(2, 0, 0, world, null, 800, 400);
        assertEquals(2, state.camera().zoom(), 1e-9);
        state.drag(0, 1000);
        assertEquals(90, state.camera().elevation(), "the camera stops straight above");
        state.fit();
        assertEquals(1, state.camera().zoom());
    }
}
