package robosim.viewer.draw;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/**
 * Draws the key: a strip under the world with the step and simulated time, a scale bar, and the
 * {@link Legend}'s entries, flowed into rows as wide as the picture. Kept outside the world so
 * that it never hides a robot or its name. The {@link WorldRenderer}'s helper.
 */
final class KeyPainter {
    /** The key's background. */
    static final Color PAPER = Color.WHITE;
    private static final Color INK = new Color(20, 20, 20);
    private static final int PAD = 4;
    private static final int GAP = 14;

    private KeyPainter() {
    }

    /** An entry placed in the strip: its sample's box, and where its words start. */
    record Placed(Legend.Entry entry, Rectangle2D sample, float textX, float baseline) { }

    /** The key's layout at one width: its height and the entries' places, from the key's top. */
    record Layout(int height, int rowHeight, List<Placed> placed) { }

    static Font font(int width) {
        return new Font(Font.SANS_SERIF, Font.PLAIN, WorldRenderer.fontSize(width));
    }

    static Layout layout(WorldDescription world, RenderOptions options, int width, boolean solid) {
        BufferedImage scratch = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = scratch.createGraphics();
        try {
            hints(g);
            g.setFont(font(width));
            return layout(g.getFontMetrics(), Legend.entries(world, options, solid), width, solid);
        } finally {
            g.dispose();
        }
    }

    /** @param solid whether for the 3D view: no first row, since the scene carries its caption and has no scale */
    private static Layout layout(FontMetrics metrics, List<Legend.Entry> entries, int width, boolean solid) {
        int row = metrics.getHeight() + 2 * PAD;
        double sampleW = metrics.getHeight() * 1.8;
        double sampleH = metrics.getHeight() * 0.8;
        List<Placed> placed = new ArrayList<>();
        double x = PAD;
        int top = solid ? 0 : row;
        for (Legend.Entry entry : entries) {
            double w = sampleW + PAD + metrics.stringWidth(entry.label());
            if (x > PAD && x + w > width - PAD) {
                x = PAD;
                top += row;
            }
            Rectangle2D sample = new Rectangle2D.Double(x, top + (row - sampleH) / 2.0, sampleW, sampleH);
            placed.add(new Placed(entry, sample, (float) (x + sampleW + PAD),
                    top + PAD + metrics.getAscent()));
            x += w + GAP;
        }
        return new Layout(entries.isEmpty() ? (solid ? 0 : row) : top + row, row, placed);
    }

    /** @param solid whether for the 3D view: the legend alone, without the caption and scale bar */
    static void draw(Graphics2D target, int top, int width, double scale, WorldDescription world,
                     Snapshot snapshot, RenderOptions options, boolean solid) {
        Graphics2D g = (Graphics2D) target.create();
        try {
            hints(g);
            g.setFont(font(width));
            FontMetrics metrics = g.getFontMetrics();
            Layout layout = layout(metrics, Legend.entries(world, options, solid), width, solid);
            g.translate(0, top);
            g.setColor(PAPER);
            g.fill(new Rectangle2D.Double(0, 0, width, layout.height()));
            int baseline = PAD + metrics.getAscent();
            g.setColor(INK);
            if (snapshot != null && options.showCaption() && !solid) {
                g.drawString(WorldRenderer.caption(snapshot), PAD, baseline);
            }
            if (!solid) {
                drawScaleBar(g, metrics, width, scale, layout.rowHeight());
            }
            for (Placed p : layout.placed()) {
                drawSample(g, p.entry(), p.sample(), scale);
                g.setColor(INK);
                g.drawString(p.entry().label(), p.textX(), p.baseline());
            }
        } finally {
            g.dispose();
        }
    }

    /** A black bar with end ticks at the right of the first row, its length written left of it. */
    private static void drawScaleBar(Graphics2D g, FontMetrics metrics, int width, double scale, int row) {
        double mm = ScaleBar.barLength(scale, width);
        double length = mm * scale;
        double right = width - 2.0 * PAD;
        double left = right - length;
        double y = row / 2.0 + 2;
        g.setColor(INK);
        g.setStroke(new BasicStroke(3f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER));
        g.draw(new Line2D.Double(left, y, right, y));
        g.setStroke(new BasicStroke(1.5f));
        g.draw(new Line2D.Double(left, y - 5, left, y + 2));
        g.draw(new Line2D.Double(right, y - 5, right, y + 2));
        String label = ScaleBar.label(mm);
        g.drawString(label, (float) (left - PAD - metrics.stringWidth(label)), PAD + metrics.getAscent());
    }

    private static void drawSample(Graphics2D g, Legend.Entry entry, Rectangle2D box, double scale) {
        double x = box.getX();
        double y = box.getY();
        double w = box.getWidth();
        double h = box.getHeight();
        Rectangle2D body = new Rectangle2D.Double(x + w * 0.15, y, w * 0.7, h);
        BasicStroke thin = new BasicStroke(1.5f);
        switch (entry.sample()) {
            case ROBOT -> robot(g, body, RobotPalette.colour(entry.robotIndex()), WorldRenderer.OUTLINE, 1.5f, true);
            case FRONT -> robot(g, body, WorldRenderer.BACKGROUND, WorldRenderer.OUTLINE, 1.5f, true);
            case NOT_CONNECTED -> robot(g, body, RobotPalette.DISCONNECTED, WorldRenderer.DISCONNECTED_OUTLINE, 1.5f, true);
            case GONE -> {
                g.setColor(WorldRenderer.GONE_OUTLINE);
                g.setStroke(WorldRenderer.GONE_STROKE);
                g.draw(body);
                g.draw(new Line2D.Double(body.getCenterX(), body.getCenterY(), body.getMaxX(), body.getCenterY()));
            }
            case STALLED -> robot(g, body, WorldRenderer.BACKGROUND, RobotPalette.STALLED, 3f, false);
            case ODOMETRY -> {
                g.setColor(INK);
                g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f,
                        new float[] {4f, 3f}, 0f));
                g.draw(body);
            }
            case SONAR -> {
                g.setColor(new Color(60, 60, 60, 170));
                g.setStroke(new BasicStroke(1.2f));
                g.draw(new Line2D.Double(x, y + h / 2, x + w - 3, y + h / 2));
                g.fill(new Ellipse2D.Double(x + w - 4.5, y + h / 2 - 1.5, 3, 3));
            }
            case LASER -> {
                g.setStroke(new BasicStroke(1f));
                for (int i = 0; i <= 4; i++) {
                    double ty = y + h * i / 4;
                    g.setColor(new Color(60, 60, 60, LaserPainter.RAY_ALPHA));
                    g.draw(new Line2D.Double(x, y + h / 2, x + w - 2, ty));
                    g.setColor(new Color(60, 60, 60, LaserPainter.HIT_ALPHA));
                    g.fill(new Rectangle2D.Double(x + w - 3, ty - 1, 2.5, 2.5));
                }
            }
            case TRAIL -> {
                g.setColor(new Color(90, 90, 90));
                g.setStroke(thin);
                Path2D path = new Path2D.Double();
                path.moveTo(x, y + h);
                path.curveTo(x + w / 3, y - h / 2, x + 2 * w / 3, y + 1.5 * h, x + w, y);
                g.draw(path);
            }
            case DRAWING -> {
                g.setColor(new Color(60, 60, 60, DrawingPainter.FILL_ALPHA));
                g.fill(new Rectangle2D.Double(x, y, w / 2, h / 2));
                g.fill(new Rectangle2D.Double(x + w / 2, y + h / 2, w / 2, h / 2));
            }
            case HEAT -> HeatPainter.drawSample(g, x + w / 2, y + h / 2, h, false);
            case GOLD -> HeatPainter.drawSample(g, x + w / 2, y + h / 2, h, true);
            case FORBIDDEN -> {
                g.setColor(WorldRenderer.FORBIDDEN);
                g.setStroke(WorldRenderer.FORBIDDEN_STROKE);
                g.draw(body);
            }
            case WALL -> {
                g.setColor(WorldRenderer.OBSTACLE);
                g.fill(body);
            }
            case GRID -> {
                g.setColor(WorldRenderer.GRID);
                g.setStroke(new BasicStroke(1f));
                for (int i = 0; i <= 3; i++) {
                    g.draw(new Line2D.Double(x + w * i / 3, y, x + w * i / 3, y + h));
                }
                g.draw(new Line2D.Double(x, y, x + w, y));
                g.draw(new Line2D.Double(x, y + h, x + w, y + h));
            }
            default -> throw new IllegalStateException("no sample for " + entry.sample());
        }
    }

    /** A robot facing right: its body, its edge, and the heading mark the world's robots carry. */
    private static void robot(Graphics2D g, Rectangle2D body, Color fill, Color edge, float edgeWidth, boolean mark) {
        g.setColor(fill);
        g.fill(body);
        g.setColor(edge);
        g.setStroke(new BasicStroke(edgeWidth));
        g.draw(body);
        if (mark) {
            double cy = body.getCenterY();
            double tip = body.getMaxX();
            double size = body.getHeight() * 0.45;
            Path2D arrow = new Path2D.Double();
            arrow.moveTo(tip, cy);
            arrow.lineTo(tip - size * 1.3, cy - size);
            arrow.lineTo(tip - size * 1.3, cy + size);
            arrow.closePath();
            g.setColor(edge);
            g.fill(arrow);
        }
    }

    static void hints(Graphics2D g) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        g.setRenderingHint(RenderingHints.KEY_RENDERING, RenderingHints.VALUE_RENDER_QUALITY);
    }
}
