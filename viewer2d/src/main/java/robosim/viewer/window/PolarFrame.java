package robosim.viewer.window;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;

/**
 * The frame of a plot of a robot's readings seen from the robot (the viewer's sensor plot, the
 * RemoteControl's): the robot in the middle facing up, a ring at the plot's range with its label,
 * and the drawing of robot-frame points (x forward, y left, mm) as rays and hits.
 */
public final class PolarFrame {
    /** The colour of the sonar rays in every such plot. */
    public static final Color SONAR = new Color(31, 119, 180);
    /** The colour of the laser's hits in every such plot. */
    public static final Color LASER = new Color(40, 40, 40);

    private final double cx;
    private final double cy;
    private final double scale;

    private PolarFrame(double cx, double cy, double scale) {
        this.cx = cx;
        this.cy = cy;
        this.scale = scale;
    }

    /**
     * Draws the ring at the range and its label, and sets the scale for what is drawn next.
     *
     * @param g      where to draw
     * @param width  the plot's width, pixels
     * @param height the plot's height, pixels
     * @param range  the range the ring stands for, mm
     * @param ring   the ring's colour
     * @param label  the label's colour
     * @return the frame, to draw the readings in
     */
    public static PolarFrame paint(Graphics2D g, int width, int height, double range, Color ring, Color label) {
        double scale = (Math.min(width, height) / 2.0 - 6) / range;
        PolarFrame f = new PolarFrame(width / 2.0, height / 2.0, scale);
        double r = range * scale;
        g.setColor(ring);
        g.draw(new Ellipse2D.Double(f.cx - r, f.cy - r, 2 * r, 2 * r));
        g.setColor(label);
        g.drawString((int) range + " mm", 4, 14);
        return f;
    }

    /**
     * @param x robot-frame x (forward), mm
     * @param y robot-frame y (left), mm
     * @return the plot point: forward is up, left is left
     */
    public double[] at(double x, double y) {
        return new double[] {cx - y * scale, cy - x * scale};
    }

    /** Draws a sonar ray from its transducer to its echo, with a dot at the echo, in the current colour. */
    public void ray(Graphics2D g, double fromX, double fromY, double toX, double toY) {
        double[] from = at(fromX, fromY);
        double[] to = at(toX, toY);
        g.setStroke(new BasicStroke(1.5f));
        g.draw(new Line2D.Double(from[0], from[1], to[0], to[1]));
        g.fill(new Ellipse2D.Double(to[0] - 2, to[1] - 2, 4, 4));
    }

    /** Draws a laser hit as a small square of the side given, in the current colour. */
    public void hit(Graphics2D g, double x, double y, double side) {
        double[] p = at(x, y);
        g.fill(new Rectangle2D.Double(p[0] - 1, p[1] - 1, side, side));
    }

    /** Draws the robot in the middle, a disc with a tick toward its front, in the colour given. */
    public void robot(Graphics2D g, Color color) {
        g.setColor(color);
        g.fill(new Ellipse2D.Double(cx - 4, cy - 4, 8, 8));
        g.setStroke(new BasicStroke(2f));
        g.draw(new Line2D.Double(cx, cy, cx, cy - 14));
    }
}
