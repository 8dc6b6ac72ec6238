package robosim.remote.window;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.util.function.Supplier;
import javax.swing.JComponent;
import robosim.remote.Readings;

/**
 * The robot's readings seen from the robot, as the viewer's sensor plot draws them: the robot in the
 * middle facing up, sonar rays in blue, laser hits as dark dots, a ring at the plot's range, and the
 * heat sensor's bearing in red when it feels a source.
 */
final class PolarPlot extends JComponent {
    private static final long serialVersionUID = 1L;
    /** The colour of the sonar rays. */
    static final Color SONAR = new Color(31, 119, 180);
    /** The colour of the laser hits. */
    static final Color LASER = new Color(40, 40, 40);
    private static final Color HEAT = new Color(214, 39, 40);
    private static final Color RING = new Color(200, 200, 200);

    private final transient Supplier<Readings> readings;

    PolarPlot(Supplier<Readings> readings) {
        this.readings = readings;
        setPreferredSize(new Dimension(280, 280));
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            int w = getWidth();
            int h = getHeight();
            g.setColor(Color.WHITE);
            g.fill(new Rectangle2D.Double(0, 0, w, h));
            Readings r = readings.get();
            double range = r == null || !(r.range() > 0) ? 5000 : r.range();
            double scale = (Math.min(w, h) / 2.0 - 6) / range;
            double cx = w / 2.0;
            double cy = h / 2.0;
            g.setColor(RING);
            g.draw(new Ellipse2D.Double(cx - range * scale, cy - range * scale, 2 * range * scale, 2 * range * scale));
            g.setColor(Color.DARK_GRAY);
            g.drawString((int) range + " mm", 4, 14);
            if (r != null) {
                g.setColor(LASER);
                for (Readings.Point p : r.laser()) {
                    double[] at = at(p, cx, cy, scale);
                    g.fill(new Rectangle2D.Double(at[0] - 1, at[1] - 1, 2.5, 2.5));
                }
                g.setColor(SONAR);
                g.setStroke(new BasicStroke(1.5f));
                for (Readings.Ray ray : r.sonar()) {
                    double[] from = at(ray.from(), cx, cy, scale);
                    double[] to = at(ray.to(), cx, cy, scale);
                    g.draw(new Line2D.Double(from[0], from[1], to[0], to[1]));
                    g.fill(new Ellipse2D.Double(to[0] - 2, to[1] - 2, 4, 4));
                }
                drawHeat(g, r.heat(), cx, cy, scale);
            }
            g.setColor(Color.BLACK);
            g.fill(new Ellipse2D.Double(cx - 4, cy - 4, 8, 8));
            g.setStroke(new BasicStroke(2f));
            g.draw(new Line2D.Double(cx, cy, cx, cy - 14));
        } finally {
            g.dispose();
        }
    }

    private static void drawHeat(Graphics2D g, Readings.Heat heat, double cx, double cy, double scale) {
        if (heat == null || heat.intensity() <= 0) {
            return;
        }
        double a = Math.toRadians(heat.bearing());
        double[] to = at(new Readings.Point(heat.distance() * Math.cos(a), heat.distance() * Math.sin(a)), cx, cy, scale);
        g.setColor(HEAT);
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND, 1f, new float[] {6f, 4f}, 0f));
        g.draw(new Line2D.Double(cx, cy, to[0], to[1]));
        g.fill(new Ellipse2D.Double(to[0] - 5, to[1] - 5, 10, 10));
    }

    /** A robot-frame point (x forward, y left) on the plot: forward is up, left is left. */
    private static double[] at(Readings.Point p, double cx, double cy, double scale) {
        return new double[] {cx - p.y() * scale, cy - p.x() * scale};
    }
}
