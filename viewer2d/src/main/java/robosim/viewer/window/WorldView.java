package robosim.viewer.window;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Rectangle2D;
import javax.swing.JComponent;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.RobotInfo;
import robosim.viewer.draw.BodyOutline;
import robosim.viewer.draw.WorldRenderer;
import robosim.viewer.view3d.SolidRenderer;

/**
 * The drawing area: the world in 2D through the {@link WorldRenderer} or in 3D through the
 * {@link SolidRenderer}, exactly as the PNG snapshots are drawn, placed by the {@link ViewState};
 * in 2D the key (step, scale bar, legend) runs along the bottom, as under the PNG images.
 * The mouse wheel zooms about the pointer; a drag pans the 2D view or turns the 3D camera.
 */
public final class WorldView extends JComponent {
    private static final long serialVersionUID = 1L;
    /** The colour around the world in the 2D view. */
    public static final Color SURROUND = new Color(200, 200, 196);
    /** The ring round the robot whose panel is open. */
    public static final Color SELECTED = new Color(230, 0, 170);
    private static final double WHEEL_STEP = 1.2;

    private final transient ViewModel model;
    private final transient ViewState state;
    private final transient WorldRenderer renderer = new WorldRenderer();

    /**
     * @param model what to show
     * @param state how to show it
     */
    public WorldView(ViewModel model, ViewState state) {
        this.model = model;
        this.state = state;
        setPreferredSize(new Dimension(800, 600));
        setOpaque(true);
        model.observe(this::repaint);
        Gestures gestures = new Gestures();
        addMouseListener(gestures);
        addMouseMotionListener(gestures);
        addMouseWheelListener(gestures);
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            int w = getWidth();
            int h = getHeight();
            WorldDescription world = model.world();
            Snapshot snapshot = model.snapshot();
            if (world == null || w < 1 || h < 1) {
                g.setColor(SURROUND);
                g.fill(new Rectangle2D.Double(0, 0, Math.max(1, w), Math.max(1, h)));
                g.setColor(Color.DARK_GRAY);
                g.drawString("waiting for the world...", 12, 24);
                return;
            }
            if (state.threeD()) {
                int scene = worldHeight(world);
                SolidRenderer.draw(g, state.project(world, snapshot, w, scene), world, snapshot, state.scene(w),
                        model.trails());
                SolidRenderer.drawKey(g, scene, w, world, state.scene(w));
                return;
            }
            g.setColor(SURROUND);
            g.fill(new Rectangle2D.Double(0, 0, w, h));
            int area = worldHeight(world);
            ViewState.Placement place = state.place(world, snapshot, w, area);
            Graphics2D inner = (Graphics2D) g.create(0, 0, w, area);
            inner.translate(place.originX(), place.originY());
            renderer.draw(inner, place.view(), world, snapshot, state.render(), model.trails());
            markSelected(inner, place);
            inner.dispose();
            renderer.drawKey(g, area, w, place.view().scale(), world, snapshot, state.render());
        } finally {
            g.dispose();
        }
    }

    /** Rings the robot whose panel is open, so it is clear which one the panel describes. */
    private void markSelected(Graphics2D g, ViewState.Placement place) {
        RobotView robot = RobotPanel.chosen(model);
        if (robot == null) {
            return;
        }
        double r = radius(robot.name()) * place.view().scale() * 1.5 + 3;
        double x = place.view().px(robot.x());
        double y = place.view().py(robot.y());
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(SELECTED);
        g.setStroke(new BasicStroke(2.5f));
        g.draw(new Ellipse2D.Double(x - r, y - r, 2 * r, 2 * r));
    }

    /**
     * The height of the part of the view the world is drawn in: the key (in 2D the step, scale bar
     * and legend; in 3D the legend) takes a strip at the bottom, as under the PNG images, so it never
     * hides the world.
     */
    private int worldHeight(WorldDescription world) {
        if (world == null) {
            return getHeight();
        }
        if (state.threeD()) {
            return Math.max(1, getHeight() - SolidRenderer.keyHeight(world, state.scene(Math.max(1, getWidth()))));
        }
        return Math.max(1, getHeight() - WorldRenderer.keyHeight(world, state.render(), Math.max(1, getWidth())));
    }

    /**
     * The world point under a point of the view, in 2D.
     *
     * @param x the view's x, px
     * @param y the view's y, px
     * @return {x, y} in mm, or {@code null} in 3D, before the world comes, or off the world
     */
    public double[] worldPoint(int x, int y) {
        WorldDescription world = model.world();
        if (world == null || state.threeD() || y >= worldHeight(world)) {
            return null;
        }
        ViewState.Placement place = state.place(world, model.snapshot(), getWidth(), worldHeight(world));
        double scale = place.view().scale();
        double wx = place.view().left() + (x - place.originX()) / scale;
        double wy = place.view().top() - (y - place.originY()) / scale;
        boolean off = wx < world.minX() || wy < world.minY() || wx > world.minX() + world.width()
                || wy > world.minY() + world.height();
        return off ? null : new double[] {wx, wy};
    }

    /**
     * The robot drawn under a point of the view: the nearest whose body's circle holds it.
     *
     * @param x the view's x, px
     * @param y the view's y, px
     * @return its name, or {@code null}
     */
    public String robotAt(int x, int y) {
        double[] p = worldPoint(x, y);
        Snapshot snapshot = model.snapshot();
        if (p == null || snapshot == null) {
            return null;
        }
        String best = null;
        double bestDistance = Double.POSITIVE_INFINITY;
        for (RobotView r : snapshot.robots()) {
            double d = Math.hypot(r.x() - p[0], r.y() - p[1]);
            if (d <= radius(r.name()) && d < bestDistance) {
                best = r.name();
                bestDistance = d;
            }
        }
        return best;
    }

    private double radius(String name) {
        for (RobotInfo info : model.world().robots()) {
            if (info.name().equals(name)) {
                return BodyOutline.radius(info.parameters());
            }
        }
        return BodyOutline.radius(null);
    }

    /** Wheel, press, drag, click (chooses the robot whose panel is shown) and the cursor readout. */
    private final class Gestures extends MouseAdapter {
        private int lastX;
        private int lastY;

        @Override
        public void mousePressed(MouseEvent e) {
            lastX = e.getX();
            lastY = e.getY();
        }

        @Override
        public void mouseClicked(MouseEvent e) {
            if (model.world() != null && !state.threeD()) {
                model.select(robotAt(e.getX(), e.getY()));
            }
        }

        @Override
        public void mouseMoved(MouseEvent e) {
            model.cursor(worldPoint(e.getX(), e.getY()));
        }

        @Override
        public void mouseExited(MouseEvent e) {
            model.cursor(null);
        }

        @Override
        public void mouseDragged(MouseEvent e) {
            state.drag(e.getX() - lastX, e.getY() - lastY);
            lastX = e.getX();
            lastY = e.getY();
            firePropertyChange("view", 0, 1);
            repaint();
        }

        @Override
        public void mouseWheelMoved(MouseWheelEvent e) {
            if (model.world() == null) {
                return;
            }
            double factor = Math.pow(WHEEL_STEP, -e.getPreciseWheelRotation());
            state.zoomAbout(factor, e.getX(), e.getY(), model.world(), model.snapshot(), getWidth(),
                    worldHeight(model.world()));
            repaint();
        }
    }
}
