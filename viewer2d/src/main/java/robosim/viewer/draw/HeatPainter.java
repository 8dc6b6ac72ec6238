package robosim.viewer.draw;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RadialGradientPaint;
import java.awt.Shape;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Point2D;
import java.util.List;
import robosim.protocol.WorldDescription.HeatSource;

/**
 * Draws heat sources: a warm radial glow of one size for all, whose opacity follows the source's
 * intensity relative to the world's strongest, and a small marker of one size for all at the
 * source itself: a round one for a plain heat source, a gold diamond for the world's gold. The {@link WorldRenderer}'s helper.
 */
final class HeatPainter {
    /** Radius of the glow: the distance at which a source's intensity is given, mm. */
    static final double GLOW_RADIUS_MM = 1000;
    /** The smallest glow radius, so that a source stays visible in a small image, px. */
    static final double MIN_GLOW_PX = 8;
    /** Diameter of the marker at each source, px. */
    static final double MARKER_PX = 7;
    /** Opacity of the strongest source's glow at its centre, 0 to 255. */
    static final int MAX_ALPHA = 210;
    /** The share of {@link #MAX_ALPHA} that even the faintest source's glow keeps. */
    static final double MIN_SHARE = 0.2;

    private static final Color CORE = new Color(255, 90, 0);
    private static final Color GLOW = new Color(255, 170, 40);
    private static final Color MARKER = new Color(230, 80, 0);
    private static final Color MARKER_RING = new Color(110, 35, 0);
    /** The gold's marker: a gold diamond, so that it reads apart from a plain heat source. */
    static final Color GOLD = new Color(255, 200, 0);

    /** Draws the glow of every source; call before the obstacles so that they stay crisp. */
    void drawGlow(Graphics2D g, ViewTransform view, List<HeatSource> heat) {
        double strongest = strongest(heat);
        double r = Math.max(MIN_GLOW_PX, GLOW_RADIUS_MM * view.scale());
        float[] stops = {0f, 0.3f, 1f};
        for (HeatSource source : heat) {
            if (!drawable(source)) {
                continue;
            }
            int alpha = alpha(source.intensity(), strongest);
            double cx = view.px(source.x());
            double cy = view.py(source.y());
            Color[] colours = {withAlpha(CORE, alpha), withAlpha(GLOW, alpha / 2), withAlpha(GLOW, 0)};
            g.setPaint(new RadialGradientPaint(new Point2D.Double(cx, cy), (float) r, stops, colours));
            g.fill(new Ellipse2D.Double(cx - r, cy - r, 2 * r, 2 * r));
        }
    }

    /** Draws a marker at every source; call after the obstacles so that none hides one. */
    void drawMarkers(Graphics2D g, ViewTransform view, List<HeatSource> heat) {
        for (HeatSource source : heat) {
            if (!drawable(source)) {
                continue;
            }
            drawMarker(g, view.px(source.x()), view.py(source.y()), source.gold());
        }
    }

    /** A plain source's round marker, or the gold's larger diamond, centred on (cx, cy) px. */
    private static void drawMarker(Graphics2D g, double cx, double cy, boolean gold) {
        double d = MARKER_PX;
        Shape marker;
        if (gold) {
            double r = d * 0.9;
            marker = ClosedPath.of(4, i -> cx + (i == 0 ? r : i == 2 ? -r : 0), i -> cy + (i == 1 ? r : i == 3 ? -r : 0));
        } else {
            marker = new Ellipse2D.Double(cx - d / 2, cy - d / 2, d, d);
        }
        g.setStroke(new BasicStroke(1f));
        g.setColor(gold ? GOLD : MARKER);
        g.fill(marker);
        g.setColor(MARKER_RING);
        g.draw(marker);
    }

    /** Draws a source for the legend: a glow of the given diameter round a marker (the gold's, for the gold). */
    static void drawSample(Graphics2D g, double cx, double cy, double diameter, boolean gold) {
        double r = diameter * 0.75;
        float[] stops = {0f, 0.3f, 1f};
        Color[] colours = {withAlpha(CORE, MAX_ALPHA), withAlpha(GLOW, MAX_ALPHA / 2), withAlpha(GLOW, 0)};
        g.setPaint(new RadialGradientPaint(new Point2D.Double(cx, cy), (float) r, stops, colours));
        g.fill(new Ellipse2D.Double(cx - r, cy - r, 2 * r, 2 * r));
        drawMarker(g, cx, cy, gold);
    }

    /**
     * @param intensity a source's intensity, greater than 0
     * @param strongest the greatest intensity in the world
     * @return the opacity of its glow's centre: {@link #MAX_ALPHA} scaled by its share of the
     *         strongest, but never below {@link #MIN_SHARE} of it
     */
    static int alpha(double intensity, double strongest) {
        double share = Math.max(MIN_SHARE, Math.min(1, intensity / strongest));
        return (int) Math.round(MAX_ALPHA * share);
    }

    private static double strongest(List<HeatSource> heat) {
        double max = 0;
        for (HeatSource source : heat) {
            if (drawable(source)) {
                max = Math.max(max, source.intensity());
            }
        }
        return max;
    }

    /** A source from a broken or hostile frame is skipped rather than breaking the drawing. */
    private static boolean drawable(HeatSource source) {
        return source != null && Double.isFinite(source.x()) && Double.isFinite(source.y())
                && source.intensity() > 0 && Double.isFinite(source.intensity());
    }

    private static Color withAlpha(Color c, int alpha) {
        return new Color(c.getRed(), c.getGreen(), c.getBlue(), alpha);
    }
}
