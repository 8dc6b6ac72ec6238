package robosim.viewer.draw;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import robosim.geometry.Pose2D;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.SonarUnit;
import robosim.protocol.WorldDescription.RobotInfo;

/**
 * Draws a robot's sonar readings as rays with a dot at each end, in any view: the caller says where
 * a point of the ground lands on the screen (the 2D view maps it flat; the 3D view draws the rays on
 * the floor).
 */
public final class SonarPainter {
    private SonarPainter() {
    }

    /**
     * Draws a ray from each transducer's mounting pose along its heading, as long as the range the
     * snapshot reports for it. Transducers without a reading, or with a negative one, are skipped, and
     * so is a robot the world does not describe (its transducers' poses are not known).
     *
     * @param g        where to draw
     * @param toScreen the view's projection of the ground
     * @param robot    the robot, with its readings
     * @param info     the robot's parameters (its transducers' poses), or null
     * @param colour   the rays' colour
     */
    public static void drawRays(Graphics2D g, TrailPainter.ToScreen toScreen, RobotView robot, RobotInfo info,
                                Color colour) {
        int[] ranges = robot.sonar();
        if (info == null || info.parameters() == null || ranges == null) {
            return;
        }
        Pose2D pose = new Pose2D(robot.x(), robot.y(), Math.toRadians(robot.th()));
        g.setColor(colour);
        g.setStroke(new BasicStroke(1.2f));
        double dot = 3;
        double[] from = new double[2];
        double[] to = new double[2];
        for (SonarUnit unit : info.parameters().sonarUnits()) {
            int i = unit.index();
            if (i < 0 || i >= ranges.length || ranges[i] < 0) {
                continue;
            }
            double heading = Math.toRadians(unit.th());
            double endX = unit.x() + ranges[i] * Math.cos(heading);
            double endY = unit.y() + ranges[i] * Math.sin(heading);
            toScreen.map(pose.worldX(endX, endY), pose.worldY(endX, endY), to);
            toScreen.map(pose.worldX(unit.x(), unit.y()), pose.worldY(unit.x(), unit.y()), from);
            g.draw(new Line2D.Double(from[0], from[1], to[0], to[1]));
            g.fill(new Ellipse2D.Double(to[0] - dot / 2, to[1] - dot / 2, dot, dot));
        }
    }
}
