package robosim.viewer.window;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import javax.swing.JComponent;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription.RobotInfo;
import robosim.viewer.draw.WorldRenderer;

/**
 * The chosen robot's readings seen from the robot: it sits in the middle facing up, its sonar rays
 * in blue, its laser's hits as dark dots, inside a ring at the sonar's maximum range.
 */
final class SensorPlot extends JComponent {
    private static final long serialVersionUID = 1L;
    /** The colour of the sonar rays. */
    static final Color SONAR = new Color(31, 119, 180);
    private static final Color LASER = new Color(40, 40, 40);

    private final transient ViewModel model;

    SensorPlot(ViewModel model) {
        this.model = model;
        setPreferredSize(new Dimension(260, 260));
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            int w = getWidth();
            int h = getHeight();
            g.setColor(WorldRenderer.BACKGROUND);
            g.fill(new Rectangle2D.Double(0, 0, w, h));
            RobotView robot = RobotPanel.chosen(model);
            if (robot == null) {
                return;
            }
            RobotInfo info = RobotPanel.info(model, robot.name());
            RobotParameters p = info == null ? null : info.parameters();
            double range = p != null && p.sonarMaxRange() > 0 ? p.sonarMaxRange() : 5000;
            double scale = (Math.min(w, h) / 2.0 - 6) / range;
            double cx = w / 2.0;
            double cy = h / 2.0;
            g.setColor(WorldRenderer.GRID);
            g.draw(new Ellipse2D.Double(cx - range * scale, cy - range * scale, 2 * range * scale, 2 * range * scale));
            g.setColor(WorldRenderer.OBSTACLE);
            g.drawString((int) range + " mm", 4, 14);
            drawLaser(g, robot, p, cx, cy, scale);
            drawSonar(g, robot, p, cx, cy, scale);
            g.setColor(WorldRenderer.OBSTACLE);
            g.fill(new Ellipse2D.Double(cx - 4, cy - 4, 8, 8));
            g.setStroke(new BasicStroke(2f));
            g.draw(new Line2D.Double(cx, cy, cx, cy - 14));
        } finally {
            g.dispose();
        }
    }

    /** A robot-frame point (x forward, y left, mm) as a plot point: forward is up, left is left. */
    private static double[] at(double x, double y, double cx, double cy, double scale) {
        return new double[] {cx - y * scale, cy - x * scale};
    }

    private static void drawSonar(Graphics2D g, RobotView robot, RobotParameters p, double cx, double cy, double scale) {
        int[] ranges = robot.sonar();
        if (p == null || ranges == null) {
            return;
        }
        g.setColor(SONAR);
        g.setStroke(new BasicStroke(1.5f));
        for (SonarUnit unit : p.sonarUnits()) {
            int i = unit.index();
            if (i < 0 || i >= ranges.length || ranges[i] < 0) {
                continue;
            }
            double th = Math.toRadians(unit.th());
            double[] from = at(unit.x(), unit.y(), cx, cy, scale);
            double[] to = at(unit.x() + ranges[i] * Math.cos(th), unit.y() + ranges[i] * Math.sin(th), cx, cy, scale);
            g.draw(new Line2D.Double(from[0], from[1], to[0], to[1]));
            g.fill(new Ellipse2D.Double(to[0] - 2, to[1] - 2, 4, 4));
        }
    }

    private static void drawLaser(Graphics2D g, RobotView robot, RobotParameters p, double cx, double cy, double scale) {
        int[] ranges = robot.laser();
        double increment = robot.laserIncrement();
        if (ranges == null || !(increment > 0)) {
            return;
        }
        double mx = p == null ? 0 : p.laserX();
        double my = p == null ? 0 : p.laserY();
        double mth = p == null ? 0 : p.laserTh();
        g.setColor(LASER);
        for (int i = 0; i < ranges.length; i++) {
            if (ranges[i] <= 0) {
                continue;
            }
            double a = Math.toRadians(mth - 90 + i * increment);
            double[] hit = at(mx + ranges[i] * Math.cos(a), my + ranges[i] * Math.sin(a), cx, cy, scale);
            g.fill(new Rectangle2D.Double(hit[0] - 1, hit[1] - 1, 2, 2));
        }
    }
}
