package robosim.viewer.view3d;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.Comparator;
import java.util.List;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.HeatSource;
import robosim.viewer.draw.ClosedPath;
import robosim.viewer.draw.SnapshotPainter;
import robosim.viewer.draw.TrailPainter;
import robosim.viewer.draw.Trails;
import robosim.viewer.draw.WorldRenderer;

/**
 * Draws the 3D view of a snapshot: the sky, the floor with its heat sources (the gold in gold), the
 * robots' trails, their sonar rays and laser scans when shown, and the outlines of robots gone from
 * the run, then every visible face of the walls, obstacles and robots from the farthest to the nearest
 * (the painter's algorithm), each in its colour shaded by the light, then the robots' names and
 * the caption; under the scene, the legend. Pure drawing, no state between calls.
 */
public final class SolidRenderer implements SnapshotPainter {
    /** The colour around the world. */
    public static final Color SKY = new Color(214, 224, 236);
    private static final Color HEAT = new Color(240, 110, 20);
    private static final Color GOLD = new Color(255, 200, 0);
    private static final Color TEXT = new Color(20, 20, 20);
    private static final double[] UP = {0, 0, 1};

    private final SceneOptions options;

    /** @param options how snapshots are drawn when used as a {@link SnapshotPainter} */
    public SolidRenderer(SceneOptions options) {
        if (options == null) {
            throw new IllegalArgumentException("null was supplied for options: they are required");
        }
        this.options = options;
    }

    @Override
    public BufferedImage paint(WorldDescription world, Snapshot snapshot, Trails trails) {
        return render(world, snapshot, options, trails);
    }

    /**
     * Draws a snapshot into a new image as wide as the options say and as high as suits the camera
     * (see {@link Projection#heightFor}).
     *
     * @param world   the static world
     * @param snapshot   the robots after one step, or {@code null} for the world alone
     * @param options the width, camera, light and what to show
     * @param trails  the robots' paths, or {@code null}
     * @return a new {@link BufferedImage#TYPE_INT_RGB} image
     */
    public static BufferedImage render(WorldDescription world, Snapshot snapshot, SceneOptions options, Trails trails) {
        int height = Projection.heightFor(world, options.camera(), options.width());
        Projection p = Projection.fit(world, options.camera(), options.width(), height, Double.NaN, Double.NaN);
        BufferedImage image = new BufferedImage(options.width(), height + keyHeight(world, options),
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            draw(g, p, world, snapshot, options, trails);
            drawKey(g, height, options.width(), world, options);
        } finally {
            g.dispose();
        }
        return image;
    }

    /**
     * The height of the legend drawn under the scene (see {@link SceneOptions#showKey}): it depends on
     * the world and the options only, so every frame of a run is the same size.
     *
     * @param world   the world
     * @param options what the scene shows
     * @return its height, px; 0 without a legend
     */
    public static int keyHeight(WorldDescription world, SceneOptions options) {
        return options.showKey() ? WorldRenderer.solidKeyHeight(world, options.shown(), options.width()) : 0;
    }

    /**
     * Draws the legend under a scene, {@link #keyHeight} high; nothing when the options show none.
     *
     * @param target  where to draw; its settings are left as they were
     * @param top     the legend's top edge, px
     * @param width   its width, px
     * @param world   the world
     * @param options what the scene shows
     */
    public static void drawKey(Graphics2D target, int top, int width, WorldDescription world, SceneOptions options) {
        if (options.showKey()) {
            new WorldRenderer().drawSolidKey(target, top, width, world, options.shown().withWidth(Math.max(1, width)));
        }
    }

    /**
     * Draws a snapshot onto any surface, such as a window's component, through a projection.
     *
     * @param target  where to draw; its settings are left as they were
     * @param p       the projection, which also gives the size of the area drawn
     * @param world   the static world
     * @param snapshot   the robots after one step, or {@code null}
     * @param options the light and what to show; its width and camera are the projection's business
     * @param trails  the robots' paths, or {@code null}
     */
    public static void draw(Graphics2D target, Projection p, WorldDescription world, Snapshot snapshot,
                            SceneOptions options, Trails trails) {
        Graphics2D g = (Graphics2D) target.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
            double[] light = options.light().towardsLight();
            g.setColor(SKY);
            g.fill(new Rectangle2D.Double(0, 0, p.width(), p.height()));
            g.setColor(Shading.shade(WorldRenderer.BACKGROUND, UP, light));
            double x0 = world.minX();
            double y0 = world.minY();
            double x1 = x0 + world.width();
            double y1 = y0 + world.height();
            g.fill(path(p, new double[] {x0, y0, 0, x1, y0, 0, x1, y1, 0, x0, y1, 0}));
            drawHeat(g, p, world.heat());
            if (trails != null && options.showTrails()) {
                drawTrails(g, p, world, snapshot, trails);
            }
            if (snapshot != null) {
                // on the floor, under the walls and robots, so that a wall hides what lies behind it
                FloorMarks.draw(g, p, world, snapshot, options);
            }
            List<Face> faces = SceneBuilder.build(world, snapshot, p);
            faces.sort(Comparator.comparingDouble(f -> f.depth(p)));
            g.setStroke(new BasicStroke(1f));
            for (Face f : faces) {
                drawFace(g, p, f, light);
            }
            if (snapshot != null && options.showNames()) {
                drawNames(g, p, snapshot);
            }
            if (snapshot != null && options.showCaption()) {
                WorldRenderer.drawCaption(g, p.width(), WorldRenderer.caption(snapshot));
            }
        } finally {
            g.dispose();
        }
    }

    private static void drawFace(Graphics2D g, Projection p, Face f, double[] light) {
        Path2D polygon = path(p, f.xyz());
        Color shaded = Shading.shade(f.base(), f.normal(), light);
        g.setColor(shaded);
        g.fill(polygon);
        // the same colour round the edge closes the hairline seams anti-aliasing leaves between pieces
        g.draw(polygon);
        if (f.mark() != null) {
            g.setColor(new Color(25, 25, 25));
            g.fill(path(p, f.mark()));
        }
        if (f.outline() != null) {
            g.setColor(f.outline());
            g.setStroke(new BasicStroke(1.5f));
            g.draw(polygon);
            g.setStroke(new BasicStroke(1f));
        }
    }

    private static void drawHeat(Graphics2D g, Projection p, List<HeatSource> heat) {
        double r = Math.max(3, 120 * p.scale());
        for (HeatSource h : heat) {
            if (h != null && Double.isFinite(h.x()) && Double.isFinite(h.y())) {
                g.setColor(h.gold() ? GOLD : HEAT);
                double x = p.px(h.x(), h.y(), 0);
                double y = p.py(h.x(), h.y(), 0);
                g.fill(new Ellipse2D.Double(x - r, y - r / 2, 2 * r, r));
            }
        }
    }

    private static void drawTrails(Graphics2D g, Projection p, WorldDescription world, Snapshot snapshot,
                                   Trails trails) {
        TrailPainter.draw(g, trails, robot -> WorldRenderer.colourOf(world, snapshot, robot), (x, y, out) -> {
            out[0] = p.px(x, y, 0);
            out[1] = p.py(x, y, 0);
        });
    }

    private static void drawNames(Graphics2D g, Projection p, Snapshot snapshot) {
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, Math.max(10, Math.min(24, p.width() / 70))));
        g.setColor(TEXT);
        for (RobotView r : snapshot.robots()) {
            if (r.name() != null && Double.isFinite(r.x()) && Double.isFinite(r.y())) {
                double z = Projection.ROBOT_HEIGHT_MM + 60;
                g.drawString(r.name(), (float) p.px(r.x(), r.y(), z) + 6, (float) p.py(r.x(), r.y(), z) - 6);
            }
        }
    }

    private static Path2D path(Projection p, double[] xyz) {
        return ClosedPath.of(xyz.length / 3, i -> p.px(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]),
                i -> p.py(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]));
    }
}
