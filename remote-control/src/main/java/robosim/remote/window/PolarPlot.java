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
import robosim.viewer.window.PolarFrame;

/**
 * The robot's readings seen from the robot, as the viewer's sensor plot draws them: the robot in the
 * middle facing up, sonar rays in blue, laser hits as dark dots, a ring at the plot's range, and the
 * heat sensor's bearing in red when it feels a source.
 */
final class PolarPlot extends JComponent {
    private static final long serialVersionUID = 1L;
    /** The colour of the sonar rays. */
    static final Color SONAR = PolarFrame.SONAR;
    /** The colour of the laser hits. */
    static final Color LASER = PolarFrame.LASER;
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
            PolarFrame f = PolarFrame.paint(g, w, h, range, RING, Color.DARK_GRAY);
            if (r != null) {
                g.setColor(LASER);
                for (Readings.Point p : r.laser()) {
                    f.hit(g, p.x(), p.y(), 2.5);
                }
                g.setColor(SONAR);
                for (Readings.Ray ray : r.sonar()) {
                    f.ray(g, ray.from().x(), ray.from().y(), ray.to().x(), ray.to().y());
                }
                drawHeat(g, f, r.heat());
            }
            f.robot(g, Color.BLACK);
        } finally {
            g.dispose();
        }
    }

    private static void drawHeat(Graphics2D g, PolarFrame f, Readings.Heat heat) {
        if (heat == null || heat.intensity() <= 0) {
            return;
        }
        double a = Math.toRadians(heat.bearing());
        double[] centre = f.at(0, 0);
        double[] to = f.at(heat.distance() * Math.cos(a), heat.distance() * Math.sin(a));
        g.setColor(HEAT);
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND, 1f, new float[] {6f, 4f}, 0f));
        g.draw(new Line2D.Double(centre[0], centre[1], to[0], to[1]));
        g.fill(new Ellipse2D.Double(to[0] - 5, to[1] - 5, 10, 10));
    }
}
