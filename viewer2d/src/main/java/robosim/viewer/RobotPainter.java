package robosim.viewer;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.Shape;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import robosim.geometry.Pose2D;
import robosim.protocol.ViewerFrame.RobotView;
import robosim.protocol.WorldDescription.RobotInfo;
import robosim.protocol.params.RobotParameters;
import robosim.protocol.params.SonarUnit;

/** Draws one robot's body, heading line, sonar rays and name; the {@link WorldRenderer}'s helper. */
final class RobotPainter {
    /** Radius drawn for a robot whose body the world does not describe. */
    static final double FALLBACK_RADIUS_MM = 200;

    private static final Color HEADING = new Color(20, 20, 20);

    void drawBody(Graphics2D g, ViewTransform view, RobotView robot, RobotInfo info, Color fill, Color outline) {
        Pose2D pose = pose(robot);
        RobotParameters p = info == null ? null : info.parameters();
        Shape body = hasRectangle(p) ? rectangle(view, pose, p) : circle(view, robot, radius(p));
        g.setColor(fill);
        g.fill(body);
        g.setColor(outline);
        g.setStroke(new BasicStroke(robot.stalled() ? 3f : 1.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(body);
        double front = hasRectangle(p) ? p.robotLengthFront() : radius(p);
        g.setColor(robot.connected() ? HEADING : outline);
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(view.px(robot.x()), view.py(robot.y()),
                view.px(pose.worldX(front, 0)), view.py(pose.worldY(front, 0))));
    }

    /**
     * Draws a ray from each transducer's mounting pose along its heading, as long as the range the
     * frame reports for it. Transducers without a reading, or with a negative one, are skipped.
     */
    void drawSonar(Graphics2D g, ViewTransform view, RobotView robot, RobotInfo info, Color colour) {
        int[] ranges = robot.sonar();
        if (info == null || info.parameters() == null || ranges == null) {
            return;
        }
        Pose2D pose = pose(robot);
        g.setColor(colour);
        g.setStroke(new BasicStroke(1.2f));
        double dot = 3;
        for (SonarUnit unit : info.parameters().sonarUnits()) {
            int i = unit.index();
            if (i < 0 || i >= ranges.length || ranges[i] < 0) {
                continue;
            }
            double heading = Math.toRadians(unit.th());
            double endX = unit.x() + ranges[i] * Math.cos(heading);
            double endY = unit.y() + ranges[i] * Math.sin(heading);
            double x1 = view.px(pose.worldX(endX, endY));
            double y1 = view.py(pose.worldY(endX, endY));
            g.draw(new Line2D.Double(view.px(pose.worldX(unit.x(), unit.y())),
                    view.py(pose.worldY(unit.x(), unit.y())), x1, y1));
            g.fill(new Ellipse2D.Double(x1 - dot / 2, y1 - dot / 2, dot, dot));
        }
    }

    /** Writes the name just above and right of the body. */
    void drawName(Graphics2D g, ViewTransform view, RobotView robot, RobotInfo info, Color colour) {
        if (robot.name() == null) {
            return;
        }
        double r = view.scale() * radius(info == null ? null : info.parameters());
        g.setColor(colour);
        g.drawString(robot.name(), (float) (view.px(robot.x()) + r * 0.8), (float) (view.py(robot.y()) - r * 0.8));
    }

    private static Pose2D pose(RobotView robot) {
        return new Pose2D(robot.x(), robot.y(), Math.toRadians(robot.th()));
    }

    private static boolean hasRectangle(RobotParameters p) {
        return p != null && p.robotWidth() > 0 && p.robotLengthFront() + p.robotLengthRear() > 0;
    }

    /** The enclosing radius from the parameters, or a fallback when they do not give one. */
    private static double radius(RobotParameters p) {
        if (p == null) {
            return FALLBACK_RADIUS_MM;
        }
        if (p.robotRadius() > 0) {
            return p.robotRadius();
        }
        double r = Math.hypot(Math.max(p.robotLengthFront(), p.robotLengthRear()), p.robotWidth() / 2);
        return r > 0 ? r : FALLBACK_RADIUS_MM;
    }

    private static Shape rectangle(ViewTransform view, Pose2D pose, RobotParameters p) {
        double front = p.robotLengthFront();
        double rear = -p.robotLengthRear();
        double half = p.robotWidth() / 2;
        double[][] corners = {{front, half}, {rear, half}, {rear, -half}, {front, -half}};
        Path2D.Double path = new Path2D.Double();
        for (int i = 0; i < corners.length; i++) {
            double x = view.px(pose.worldX(corners[i][0], corners[i][1]));
            double y = view.py(pose.worldY(corners[i][0], corners[i][1]));
            if (i == 0) {
                path.moveTo(x, y);
            } else {
                path.lineTo(x, y);
            }
        }
        path.closePath();
        return path;
    }

    private static Shape circle(ViewTransform view, RobotView robot, double radiusMm) {
        double r = radiusMm * view.scale();
        return new Ellipse2D.Double(view.px(robot.x()) - r, view.py(robot.y()) - r, 2 * r, 2 * r);
    }
}
