package robosim.viewer.window;

import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;
import robosim.viewer.draw.RenderOptions;
import robosim.viewer.draw.ViewTransform;
import robosim.viewer.view3d.Camera;
import robosim.viewer.view3d.Light;
import robosim.viewer.view3d.Projection;
import robosim.viewer.view3d.SceneOptions;

/**
 * How the window shows the world: what is drawn (the {@link RenderOptions} toggles), 2D or 3D,
 * the 2D zoom and pan, the 3D camera and light, and the robot followed. Plain state with the
 * arithmetic of the mouse gestures, kept apart from Swing so that it is tested directly.
 *
 * <p>At zoom 1 with no pan the 2D view is placed exactly as a PNG snapshot of the panel's width is
 * drawn, so the window and the files show the same pixels.
 */
public final class ViewState {
    /** The smallest 2D zoom. */
    public static final double MIN_ZOOM = 0.2;
    /** The largest 2D zoom. */
    public static final double MAX_ZOOM = 200;

    private RenderOptions render = RenderOptions.of(800).withTrails(true);
    private boolean threeD;
    private Camera camera = Camera.DEFAULT;
    private Light light = Light.DEFAULT;
    private double zoom = 1;
    private double panX;
    private double panY;
    private String follow;

    /**
     * Where the 2D world goes in a panel.
     *
     * @param view    the mapping from world mm to pixels, from the world's top left corner
     * @param originX the panel x of the world's top left corner
     * @param originY the panel y of the world's top left corner
     */
    public record Placement(ViewTransform view, double originX, double originY) { }

    /** @return the 2D drawing options */
    public RenderOptions render() {
        return render;
    }

    /** @param options the new drawing options; the width is ignored */
    public void setRender(RenderOptions options) {
        render = options;
    }

    /** @return whether the 3D view is shown */
    public boolean threeD() {
        return threeD;
    }

    /** @param show whether to show the 3D view */
    public void setThreeD(boolean show) {
        threeD = show;
    }

    /** @return the 3D camera */
    public Camera camera() {
        return camera;
    }

    /** @param newCamera the 3D camera */
    public void setCamera(Camera newCamera) {
        camera = newCamera;
    }

    /** @return the 3D light */
    public Light light() {
        return light;
    }

    /** @param newLight the 3D light */
    public void setLight(Light newLight) {
        light = newLight;
    }

    /** @return the robot kept in the centre, or {@code null} */
    public String follow() {
        return follow;
    }

    /** @param robot the robot to keep in the centre, or {@code null} to stop following */
    public void setFollow(String robot) {
        follow = robot;
    }

    /** @return the 2D zoom, 1 fitting the world to the panel */
    public double zoom() {
        return zoom;
    }

    /** Back to the whole world in view: zoom 1, no pan, the camera's zoom 1. */
    public void fit() {
        zoom = 1;
        panX = 0;
        panY = 0;
        camera = camera.withZoom(1);
    }

    /**
     * Places the 2D world in a panel: fitted and centred, then zoomed, panned, or centred on the
     * followed robot.
     *
     * @param world  the world
     * @param snapshot  the snapshot, for the followed robot's position; may be {@code null}
     * @param width  panel width, px
     * @param height panel height, px
     * @return the placement
     */
    public Placement place(WorldDescription world, Snapshot snapshot, int width, int height) {
        ViewTransform base = ViewTransform.fit(world, fitWidth(world, width, height));
        ViewTransform view = zoom == 1 ? base : new ViewTransform(base.scale() * zoom,
                (int) Math.ceil(world.width() * base.scale() * zoom), (int) Math.ceil(world.height() * base.scale() * zoom),
                base.left(), base.top());
        RobotView robot = followed(snapshot);
        if (robot != null) {
            return new Placement(view, width / 2.0 - view.px(robot.x()), height / 2.0 - view.py(robot.y()));
        }
        return new Placement(view, (width - view.width()) / 2.0 + panX, (height - view.height()) / 2.0 + panY);
    }

    /** The widest PNG width whose image fits the panel, so that zoom 1 matches the files exactly. */
    private static int fitWidth(WorldDescription world, int width, int height) {
        int w = (int) Math.max(1, Math.min(width, Math.floor(Math.max(1, height) * world.width() / world.height())));
        while (w > 1 && ViewTransform.fit(world, w).height() > Math.max(1, height)) {
            w--;
        }
        return w;
    }

    /**
     * The 3D projection for a panel, centred on the followed robot if there is one.
     *
     * @param world  the world
     * @param snapshot  the snapshot, or {@code null}
     * @param width  panel width, px
     * @param height panel height, px
     * @return the projection
     */
    public Projection project(WorldDescription world, Snapshot snapshot, int width, int height) {
        RobotView robot = followed(snapshot);
        return Projection.fit(world, camera, Math.max(1, width), Math.max(1, height),
                robot == null ? Double.NaN : robot.x(), robot == null ? Double.NaN : robot.y());
    }

    /**
     * @param width panel width, px
     * @return the 3D drawing options matching the 2D toggles
     */
    public SceneOptions scene(int width) {
        return new SceneOptions(Math.max(1, width), camera, light, render.showNames(), render.showTrails(), true,
                render.showSonar(), render.showLaser(), true);
    }

    /**
     * Zooms about a point of the panel, which stays over the same world point (2D), or zooms the
     * camera (3D).
     *
     * @param factor how much to magnify, such as 1.25, or 0.8 to shrink
     * @param x      the panel x to zoom about
     * @param y      the panel y
     * @param world  the world
     * @param snapshot  the snapshot, or {@code null}
     * @param width  panel width
     * @param height panel height
     */
    public void zoomAbout(double factor, double x, double y, WorldDescription world, Snapshot snapshot,
                          int width, int height) {
        if (threeD) {
            camera = camera.withZoom(camera.zoom() * factor);
            return;
        }
        Placement before = place(world, snapshot, width, height);
        double newZoom = Math.max(MIN_ZOOM, Math.min(MAX_ZOOM, zoom * factor));
        double k = newZoom / zoom;
        zoom = newZoom;
        ViewTransform after = place(world, null, width, height).view();
        panX = x - (x - before.originX()) * k - (width - after.width()) / 2.0;
        panY = y - (y - before.originY()) * k - (height - after.height()) / 2.0;
    }

    /**
     * A mouse drag: pans the 2D view (and stops following), or turns the 3D camera, half a degree
     * per pixel.
     *
     * @param dx pixels dragged right
     * @param dy pixels dragged down
     */
    public void drag(double dx, double dy) {
        if (threeD) {
            camera = camera.withAzimuth(camera.azimuth() - dx * 0.5).withElevation(camera.elevation() + dy * 0.5);
            return;
        }
        follow = null;
        panX += dx;
        panY += dy;
    }

    private RobotView followed(Snapshot snapshot) {
        if (follow == null || snapshot == null) {
            return null;
        }
        for (RobotView r : snapshot.robots()) {
            if (follow.equals(r.name()) && Double.isFinite(r.x()) && Double.isFinite(r.y())) {
                return r;
            }
        }
        return null;
    }
}
