package robosim.viewer.window;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
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
    static final Color SONAR = PolarFrame.SONAR;
    private static final Color LASER = PolarFrame.LASER;

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
            PolarFrame f = PolarFrame.paint(g, w, h, range, WorldRenderer.GRID, WorldRenderer.OBSTACLE);
            drawLaser(g, f, robot, p);
            drawSonar(g, f, robot, p);
            f.robot(g, WorldRenderer.OBSTACLE);
        } finally {
            g.dispose();
        }
    }

    private static void drawSonar(Graphics2D g, PolarFrame f, RobotView robot, RobotParameters p) {
        int[] ranges = robot.sonar();
        if (p == null || ranges == null) {
            return;
        }
        g.setColor(SONAR);
        for (SonarUnit unit : p.sonarUnits()) {
            int i = unit.index();
            if (i < 0 || i >= ranges.length || ranges[i] < 0) {
                continue;
            }
            double th = Math.toRadians(unit.th());
            f.ray(g, unit.x(), unit.y(), unit.x() + ranges[i] * Math.cos(th), unit.y() + ranges[i] * Math.sin(th));
        }
    }

    private static void drawLaser(Graphics2D g, PolarFrame f, RobotView robot, RobotParameters p) {
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
            f.hit(g, mx + ranges[i] * Math.cos(a), my + ranges[i] * Math.sin(a), 2);
        }
    }
}
