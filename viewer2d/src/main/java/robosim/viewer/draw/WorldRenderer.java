package robosim.viewer.draw;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import robosim.protocol.Colors;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.Obstacle;
import robosim.protocol.WorldDescription.RobotInfo;

/**
 * Draws one snapshot of the world: background, optional grid, heat sources, obstacles (in the
 * colours the world gives them), a map's forbidden lines and areas, border,
 * optionally the robots' drawings the snapshot carries (see {@link Drawings}), optional trails,
 * the movable objects (pucks) where the snapshot puts them,
 * robots (one that has gone from the run, as the snapshot's events say, as a dashed outline; see
 * {@link Departures}), optional laser scans, sonar rays, odometry ghosts and names; and under the world a key
 * with the step and the simulated time, a scale bar and a legend. Pure drawing: no I/O, no sockets, no clocks, no state between calls, so one
 * renderer may serve several threads, and the window, recorder and replay views can share it.
 *
 * <p>World coordinates are mm with +y up and headings in degrees counter-clockwise from +x; the
 * {@link ViewTransform} flips them into the image.
 */
public final class WorldRenderer {
    /** The colour of free space. */
    public static final Color BACKGROUND = new Color(248, 248, 244);
    /** The fill of walls and obstacles. */
    public static final Color OBSTACLE = new Color(64, 64, 64);
    /** The colour of the world's border. */
    public static final Color BORDER = Color.BLACK;

    /** The colour of the grid's lines. */
    public static final Color GRID = new Color(214, 218, 226);

    /** The dashed outline of a map's forbidden lines and areas. */
    public static final Color FORBIDDEN = new Color(200, 40, 40);
    /** The dashes of a map's forbidden lines and areas. */
    static final BasicStroke FORBIDDEN_STROKE = new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f,
            new float[] {6f, 4f}, 0f);
    /** The outline of a robot's body. */
    static final Color OUTLINE = new Color(20, 20, 20);
    static final Color DISCONNECTED_OUTLINE = new Color(130, 130, 130);
    /** The dashed outline of a robot gone from the run, where it stopped. */
    public static final Color GONE_OUTLINE = DISCONNECTED_OUTLINE;
    /** The dashes of a robot gone from the run. */
    public static final BasicStroke GONE_STROKE = new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND,
            10f, new float[] {5f, 4f}, 0f);
    private static final Color CAPTION_BACKDROP = new Color(255, 255, 255, 200);

    private final RobotPainter robots = new RobotPainter();
    private final CameraPainter cameras = new CameraPainter();
    private final HeatPainter heat = new HeatPainter();

    /** A renderer; it holds no state, so one can be shared. */
    public WorldRenderer() {
    }

    /**
     * Draws a snapshot into a new image as wide as the options say: the world, as high as its
     * aspect ratio makes it, and under it the key (see {@link #keyHeight}).
     *
     * @param world   the static world
     * @param snapshot   the robots after one step, or {@code null} to draw the world alone
     * @param options the image width and what to show
     * @return a new {@link BufferedImage#TYPE_INT_RGB} image
     * @throws IllegalArgumentException if the world's size is not positive or the image would be
     *                                  too tall (see {@link ViewTransform#fit})
     */
    public BufferedImage render(WorldDescription world, Snapshot snapshot, RenderOptions options) {
        return render(world, snapshot, options, null);
    }

    /**
     * Draws a snapshot, with the robots' paths when the options show trails, into a new image.
     *
     * @param world   the static world
     * @param snapshot   the robots after one step, or {@code null} to draw the world alone
     * @param options the image width and what to show
     * @param trails  the robots' paths so far, or {@code null}
     * @return a new {@link BufferedImage#TYPE_INT_RGB} image
     * @throws IllegalArgumentException if the world cannot be drawn at that width
     */
    public BufferedImage render(WorldDescription world, Snapshot snapshot, RenderOptions options, Trails trails) {
        ViewTransform view = ViewTransform.fit(world, options.width());
        int key = keyHeight(world, options, view.width());
        BufferedImage image = new BufferedImage(view.width(), view.height() + key, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            draw(g, view, world, snapshot, options, trails);
            drawKey(g, view.height(), view.width(), view.scale(), world, snapshot, options);
        } finally {
            g.dispose();
        }
        return image;
    }

    /**
     * Draws a snapshot onto any surface, such as a window's component or an image. Only the
     * rectangle from (0, 0) to the transform's width and height is drawn, without the key; the
     * options' width is ignored in favour of the transform's. The graphics' settings are left as
     * they were.
     *
     * @param target  where to draw
     * @param view    the mapping from world mm to pixels
     * @param world   the static world
     * @param snapshot   the robots after one step, or {@code null} to draw the world alone
     * @param options what to show
     */
    public void draw(Graphics2D target, ViewTransform view, WorldDescription world, Snapshot snapshot,
                     RenderOptions options) {
        draw(target, view, world, snapshot, options, null);
    }

    /**
     * Draws a snapshot onto any surface, with the robots' paths when the options show trails.
     *
     * @param target  where to draw
     * @param view    the mapping from world mm to pixels
     * @param world   the static world
     * @param snapshot   the robots after one step, or {@code null} to draw the world alone
     * @param options what to show
     * @param trails  the robots' paths so far, or {@code null}
     */
    public void draw(Graphics2D target, ViewTransform view, WorldDescription world, Snapshot snapshot,
                     RenderOptions options, Trails trails) {
        Graphics2D g = (Graphics2D) target.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
            g.setRenderingHint(RenderingHints.KEY_RENDERING, RenderingHints.VALUE_RENDER_QUALITY);
            drawWorld(g, view, world, options.showGrid());
            if (options.showDrawings()) {
                DrawingPainter.draw(g, view, snapshot, name -> colourOf(world, snapshot, name));
            }
            if (trails != null && options.showTrails()) {
                TrailPainter.draw(g, trails, name -> colourOf(world, snapshot, name), (x, y, out) -> {
                    out[0] = view.px(x);
                    out[1] = view.py(y);
                });
            }
            ObjectPainter.draw(g, view, world, snapshot);
            if (snapshot != null) {
                drawRobots(g, view, world, snapshot, options);
            }
        } finally {
            g.dispose();
        }
    }

    /**
     * The caption drawn on a snapshot, for example {@code "step 120  t=12.0 s"}.
     *
     * @param snapshot the snapshot
     * @return its step and simulated time
     */
    public static String caption(Snapshot snapshot) {
        return String.format(Locale.ROOT, "step %d  t=%.1f s", snapshot.step(), snapshot.timeMs() / 1000.0);
    }

    /**
     * The height of the key drawn under the world: a row with the step, the time and the scale
     * bar, then the legend's rows. It depends on the world, the options and the width only, so
     * every frame of a run is the same size.
     *
     * @param world   the world
     * @param options what is shown, which the legend explains
     * @param width   the key's width, px
     * @return its height, px
     */
    public static int keyHeight(WorldDescription world, RenderOptions options, int width) {
        return KeyPainter.layout(world, options, width, false).height();
    }

    /**
     * The height of the key drawn under a 3D scene: the legend alone (the scene carries its caption,
     * and an oblique view has no one scale), without what only the 2D view draws (odometry ghosts,
     * drawings, forbidden zones, the grid).
     *
     * @param world the world
     * @param shown what the scene shows (see {@code SceneOptions.shown})
     * @param width the key's width, px
     * @return its height, px; 0 when there is nothing to explain
     */
    public static int solidKeyHeight(WorldDescription world, RenderOptions shown, int width) {
        return KeyPainter.layout(world, shown, width, true).height();
    }

    /**
     * Draws the key of a 3D scene, {@link #solidKeyHeight} high, across a surface.
     *
     * @param target where to draw; its settings are left as they were
     * @param top    the key's top edge on the surface, px
     * @param width  the key's width, px
     * @param world  the world
     * @param shown  what the scene shows
     */
    public void drawSolidKey(Graphics2D target, int top, int width, WorldDescription world, RenderOptions shown) {
        KeyPainter.draw(target, top, width, 1, world, null, shown, true);
    }

    /**
     * The words of the legend under a 3D scene, in order (see {@link #legend}).
     *
     * @param world the world
     * @param shown what the scene shows
     * @return the entries' words
     */
    public static List<String> solidLegend(WorldDescription world, RenderOptions shown) {
        return Legend.entries(world, shown, true).stream().map(Legend.Entry::label).toList();
    }

    /**
     * Draws the key, {@link #keyHeight} high, across a surface: the step and simulated time (when
     * the options show the caption) and a scale bar on its first row, then the legend.
     *
     * @param target   where to draw; its settings are left as they were
     * @param top      the key's top edge on the surface, px
     * @param width    the key's width, px
     * @param scale    pixels per mm of the world as drawn beside it, for the scale bar
     * @param world    the world
     * @param snapshot the snapshot drawn, or {@code null}
     * @param options  what is shown
     */
    public void drawKey(Graphics2D target, int top, int width, double scale, WorldDescription world,
                        Snapshot snapshot, RenderOptions options) {
        KeyPainter.draw(target, top, width, scale, world, snapshot, options, false);
    }

    /**
     * The words of the legend drawn for a world with these options, in order: one entry per robot
     * of the world (its name beside its colour), then the robots' states and what else is drawn.
     *
     * @param world   the world
     * @param options what is shown
     * @return the entries' words
     */
    public static List<String> legend(WorldDescription world, RenderOptions options) {
        return Legend.entries(world, options).stream().map(Legend.Entry::label).toList();
    }

    private void drawWorld(Graphics2D g, ViewTransform view, WorldDescription world, boolean grid) {
        g.setColor(BACKGROUND);
        g.fill(new Rectangle2D.Double(0, 0, view.width(), view.height()));
        if (grid) {
            drawGrid(g, view, world);
        }
        heat.drawGlow(g, view, world.heat());
        for (Obstacle obstacle : world.obstacles()) {
            Path2D polygon = polygon(view, obstacle.xy());
            if (polygon != null) {
                g.setColor(colourOf(obstacle));
                g.fill(polygon);
            }
        }
        heat.drawMarkers(g, view, world.heat());
        drawZones(g, view, world);
        // A 2 px stroke centred 1 px inside the edge covers exactly the outermost two pixels.
        g.setColor(BORDER);
        g.setStroke(new BasicStroke(2f));
        g.draw(new Rectangle2D.Double(1, 1, view.width() - 2.0, view.height() - 2.0));
    }

    /** Light lines at every multiple of the grid's spacing: through (0, 0), wherever the world starts. */
    private static void drawGrid(Graphics2D g, ViewTransform view, WorldDescription world) {
        double spacing = ScaleBar.gridSpacing(Math.max(world.width(), world.height()));
        double x0 = world.minX();
        double y0 = world.minY();
        double x1 = x0 + world.width();
        double y1 = y0 + world.height();
        g.setColor(GRID);
        g.setStroke(new BasicStroke(1f));
        for (double x = (Math.floor(x0 / spacing) + 1) * spacing; x < x1; x += spacing) {
            g.draw(new Line2D.Double(view.px(x), view.py(y0), view.px(x), view.py(y1)));
        }
        for (double y = (Math.floor(y0 / spacing) + 1) * spacing; y < y1; y += spacing) {
            g.draw(new Line2D.Double(view.px(x0), view.py(y), view.px(x1), view.py(y)));
        }
    }

    /** A map's forbidden lines and areas: dashed red outlines, drawn over the floor, never solid. */
    private static void drawZones(Graphics2D g, ViewTransform view, WorldDescription world) {
        if (world.zones().isEmpty()) {
            return;
        }
        g.setColor(FORBIDDEN);
        g.setStroke(FORBIDDEN_STROKE);
        for (WorldDescription.Zone zone : world.zones()) {
            double[] xy = zone.xy();
            if (xy == null || xy.length < 4) {
                continue;
            }
            Path2D path = new Path2D.Double();
            path.moveTo(view.px(xy[0]), view.py(xy[1]));
            for (int i = 2; i + 1 < xy.length; i += 2) {
                path.lineTo(view.px(xy[i]), view.py(xy[i + 1]));
            }
            if (zone.area()) {
                path.closePath();
            }
            g.draw(path);
        }
    }

    /**
     * An obstacle's colour as the views draw it: the colour its world file gives it (a name or
     * {@code #rrggbb}, see {@link Colors}), or {@link #OBSTACLE} when it gives none (or one no
     * viewer knows, from a newer Environment).
     *
     * @param obstacle the obstacle
     * @return its colour
     */
    public static Color colourOf(Obstacle obstacle) {
        if (obstacle.color() == null) {
            return OBSTACLE;
        }
        try {
            return new Color(Colors.parse(obstacle.color()));
        } catch (IllegalArgumentException e) {
            return OBSTACLE;
        }
    }

    /** @return the ring as a closed pixel path, or {@code null} if it has fewer than 3 points */
    private static Path2D polygon(ViewTransform view, double[] xy) {
        if (xy == null || xy.length < 6) {
            return null;
        }
        return ClosedPath.of(xy.length / 2, i -> view.px(xy[2 * i]), i -> view.py(xy[2 * i + 1]));
    }

    private void drawRobots(Graphics2D g, ViewTransform view, WorldDescription world, Snapshot snapshot,
                            RenderOptions options) {
        Map<String, Integer> indexByName = new HashMap<>();
        List<RobotInfo> infos = world.robots();
        for (int i = 0; i < infos.size(); i++) {
            indexByName.putIfAbsent(infos.get(i).name(), i);
        }
        List<RobotView> views = snapshot.robots();
        // A robot the world does not list still gets a colour of its own, after the listed ones.
        int[] colourIndex = new int[views.size()];
        RobotInfo[] info = new RobotInfo[views.size()];
        for (int i = 0; i < views.size(); i++) {
            Integer known = indexByName.get(views.get(i).name());
            colourIndex[i] = known != null ? known : infos.size() + i;
            info[i] = known != null ? infos.get(known) : null;
        }
        TrailPainter.ToScreen flat = (x, y, out) -> {
            out[0] = view.px(x);
            out[1] = view.py(y);
        };
        boolean[] gone = new boolean[views.size()];
        for (int i = 0; i < views.size(); i++) {
            gone[i] = Departures.gone(snapshot, views.get(i));
        }
        // a robot gone from the run senses nothing: only its body is left
        for (int i = 0; i < views.size(); i++) {
            if (gone[i]) {
                continue;
            }
            RobotView robot = views.get(i);
            Color colour = robotColour(robot, colourIndex[i]);
            if (options.showLaser()) {
                LaserPainter.drawScan(g, flat, robot, info[i], colour);
            }
            cameras.drawFieldOfView(g, view, robot, colour);
        }
        if (options.showSonar()) {
            for (int i = 0; i < views.size(); i++) {
                if (!gone[i]) {
                    SonarPainter.drawRays(g, flat, views.get(i), info[i], rayColour(views.get(i), colourIndex[i]));
                }
            }
        }
        for (int i = 0; i < views.size(); i++) {
            RobotView robot = views.get(i);
            if (gone[i]) {
                robots.drawGone(g, view, robot, info[i], GONE_OUTLINE);
                continue;
            }
            Color fill = robotColour(robot, colourIndex[i]);
            Color outline = robot.stalled() ? RobotPalette.STALLED
                    : robot.connected() ? OUTLINE : DISCONNECTED_OUTLINE;
            robots.drawBody(g, view, robot, info[i], fill, outline);
        }
        if (options.showOdometry()) {
            for (int i = 0; i < views.size(); i++) {
                if (!gone[i]) {
                    robots.drawGhost(g, view, views.get(i), info[i], robotColour(views.get(i), colourIndex[i]).darker());
                }
            }
        }
        if (options.showNames()) {
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, fontSize(view.width())));
            for (int i = 0; i < views.size(); i++) {
                robots.drawName(g, view, views.get(i), info[i],
                        views.get(i).connected() ? OUTLINE : DISCONNECTED_OUTLINE);
            }
        }
    }

    /**
     * @param robot       a robot
     * @param colourIndex its index among the world's robots (its colour)
     * @return the colour of its sonar rays: its own, a little see-through
     */
    public static Color rayColour(RobotView robot, int colourIndex) {
        Color c = robotColour(robot, colourIndex);
        return new Color(c.getRed(), c.getGreen(), c.getBlue(), 170);
    }

    /**
     * @param robot       a robot
     * @param colourIndex its index among the world's robots
     * @return its colour: its own while connected, else grey
     */
    public static Color robotColour(RobotView robot, int colourIndex) {
        return robot.connected() ? RobotPalette.colour(colourIndex) : RobotPalette.DISCONNECTED;
    }

    /**
     * A robot's colour as the robots are drawn: by its index in the world, or after the world's
     * robots by its index in the snapshot; grey when it is not known. Whether it is connected is left to
     * the caller, which draws a disconnected robot grey.
     *
     * @param world the world
     * @param snapshot the snapshot, or {@code null}
     * @param name  the robot's name
     * @return its colour
     */
    public static Color colourOf(WorldDescription world, Snapshot snapshot, String name) {
        List<RobotInfo> infos = world.robots();
        for (int i = 0; i < infos.size(); i++) {
            if (infos.get(i).name().equals(name)) {
                return RobotPalette.colour(i);
            }
        }
        List<RobotView> views = snapshot == null ? List.of() : snapshot.robots();
        for (int i = 0; i < views.size(); i++) {
            if (name.equals(views.get(i).name())) {
                return RobotPalette.colour(infos.size() + i);
            }
        }
        return RobotPalette.DISCONNECTED;
    }

    /**
     * Writes a caption on a translucent box in the top left corner, as snapshots carry it, so that
     * views drawn elsewhere (the 3D view, a window) label their snapshots alike.
     *
     * @param target     where to draw; its settings are left as they were
     * @param imageWidth the width of the image, which sets the font size
     * @param text       the caption
     */
    public static void drawCaption(Graphics2D target, int imageWidth, String text) {
        Graphics2D g = (Graphics2D) target.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, fontSize(imageWidth)));
            FontMetrics metrics = g.getFontMetrics();
            int pad = 4;
            int boxWidth = metrics.stringWidth(text) + 2 * pad;
            int boxHeight = metrics.getHeight() + 2 * pad;
            g.setColor(CAPTION_BACKDROP);
            g.fill(new Rectangle2D.Double(3, 3, boxWidth, boxHeight));
            g.setColor(OUTLINE);
            g.drawString(text, 3 + pad, 3 + pad + metrics.getAscent());
        } finally {
            g.dispose();
        }
    }

    /** Text grows with the image but stays readable on small ones. */
    static int fontSize(int imageWidth) {
        return Math.max(10, Math.min(24, imageWidth / 70));
    }
}
