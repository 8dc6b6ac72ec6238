package robosim.viewer.draw;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.Shape;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import robosim.geometry.Pose2D;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription.RobotInfo;
import robosim.protocol.RobotParameters;

/**
 * Draws one robot's body, heading line and mark (or, for a robot gone from the run, a dashed
 * outline), name and odometry ghost; the
 * {@link WorldRenderer}'s helper.
 */
final class RobotPainter {
    /** How far the odometry may be from the true position before its ghost is drawn, mm. */
    static final double ODOMETRY_TOLERANCE_MM = 1;
    /** How far the odometry's heading may be from the true heading before its ghost is drawn, degrees. */
    static final double ODOMETRY_TOLERANCE_DEG = 0.5;

    private static final Color HEADING = new Color(20, 20, 20);

    void drawBody(Graphics2D g, ViewTransform view, RobotView robot, RobotInfo info, Color fill, Color outline) {
        Pose2D pose = pose(robot);
        RobotParameters p = info == null ? null : info.parameters();
        Shape body = body(view, pose, p);
        g.setColor(fill);
        g.fill(body);
        g.setColor(outline);
        g.setStroke(new BasicStroke(robot.stalled() ? 3f : 1.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(body);
        double front = BodyOutline.front(p);
        g.setColor(robot.connected() ? HEADING : outline);
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(view.px(robot.x()), view.py(robot.y()),
                view.px(pose.worldX(front, 0)), view.py(pose.worldY(front, 0))));
        g.fill(arrowhead(view, pose, front, BodyOutline.isRectangle(p) ? p.robotWidth() / 2 : BodyOutline.radius(p)));
    }

    /**
     * Draws a robot that has gone from the run where it stopped (its body stays in the world): a
     * dashed outline and a dashed heading line, unfilled, so that it reads apart from a robot whose
     * program has not connected yet.
     */
    void drawGone(Graphics2D g, ViewTransform view, RobotView robot, RobotInfo info, Color outline) {
        Pose2D pose = pose(robot);
        RobotParameters p = info == null ? null : info.parameters();
        g.setColor(outline);
        g.setStroke(WorldRenderer.GONE_STROKE);
        g.draw(body(view, pose, p));
        double front = BodyOutline.front(p);
        g.draw(new Line2D.Double(view.px(robot.x()), view.py(robot.y()),
                view.px(pose.worldX(front, 0)), view.py(pose.worldY(front, 0))));
    }

    /**
     * The heading mark: a triangle whose tip is the body's front, 0.6 as long as the front reaches
     * and at most 0.75 of the half width wide each side, so it reads at a glance which way the robot faces.
     */
    private static Shape arrowhead(ViewTransform view, Pose2D pose, double front, double halfWidth) {
        double length = front * 0.6;
        double half = Math.min(length * 0.7, halfWidth * 0.75);
        double[][] corners = {{front, 0}, {front - length, half}, {front - length, -half}};
        return ClosedPath.of(corners.length, i -> view.px(pose.worldX(corners[i][0], corners[i][1])),
                i -> view.py(pose.worldY(corners[i][0], corners[i][1])));
    }

    /**
     * Draws a dashed outline of the body, and a dashed heading line, where the robot believes it
     * is, if that is more than {@link #ODOMETRY_TOLERANCE_MM} or {@link #ODOMETRY_TOLERANCE_DEG}
     * away from where it is.
     */
    void drawGhost(Graphics2D g, ViewTransform view, RobotView robot, RobotInfo info, Color colour) {
        if (!odometryDiffers(robot)) {
            return;
        }
        Pose2D believed = new Pose2D(robot.odoX(), robot.odoY(), Math.toRadians(robot.odoTh()));
        RobotParameters p = info == null ? null : info.parameters();
        double front = BodyOutline.front(p);
        g.setColor(colour);
        g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f,
                new float[] {6f, 4f}, 0f));
        g.draw(body(view, believed, p));
        g.draw(new Line2D.Double(view.px(believed.x()), view.py(believed.y()),
                view.px(believed.worldX(front, 0)), view.py(believed.worldY(front, 0))));
    }

    /** @return whether the odometry pose is far enough from the true pose to be told apart */
    static boolean odometryDiffers(RobotView robot) {
        double apart = Math.hypot(robot.odoX() - robot.x(), robot.odoY() - robot.y());
        double turned = Math.abs(Math.IEEEremainder(robot.odoTh() - robot.th(), 360));
        // Written so that a NaN anywhere draws no ghost rather than a broken one.
        return Double.isFinite(apart) && Double.isFinite(turned)
                && (apart > ODOMETRY_TOLERANCE_MM || turned > ODOMETRY_TOLERANCE_DEG);
    }

    /**
     * Writes the name just above and right of the body, or below it or to its left where the
     * world's edge would cut the name off.
     */
    void drawName(Graphics2D g, ViewTransform view, RobotView robot, RobotInfo info, Color colour) {
        if (robot.name() == null) {
            return;
        }
        double r = view.scale() * BodyOutline.radius(info == null ? null : info.parameters());
        FontMetrics metrics = g.getFontMetrics();
        double cx = view.px(robot.x());
        double cy = view.py(robot.y());
        double x = cx + r * 0.8;
        if (x + metrics.stringWidth(robot.name()) > view.width() - 2) {
            x = cx - r * 0.8 - metrics.stringWidth(robot.name());
        }
        double baseline = cy - r * 0.8;
        if (baseline - metrics.getAscent() < 2) {
            baseline = cy + r * 0.8 + metrics.getAscent();
        }
        g.setColor(colour);
        g.drawString(robot.name(), (float) x, (float) baseline);
    }

    private static Pose2D pose(RobotView robot) {
        return new Pose2D(robot.x(), robot.y(), Math.toRadians(robot.th()));
    }

    /** @return the body's rectangle, or its enclosing circle when the parameters give no rectangle */
    private static Shape body(ViewTransform view, Pose2D pose, RobotParameters p) {
        return BodyOutline.isRectangle(p) ? rectangle(view, pose, p) : circle(view, pose, BodyOutline.radius(p));
    }

    private static Shape rectangle(ViewTransform view, Pose2D pose, RobotParameters p) {
        double front = p.robotLengthFront();
        double rear = -p.robotLengthRear();
        double half = p.robotWidth() / 2;
        double[][] corners = {{front, half}, {rear, half}, {rear, -half}, {front, -half}};
        return ClosedPath.of(corners.length, i -> view.px(pose.worldX(corners[i][0], corners[i][1])),
                i -> view.py(pose.worldY(corners[i][0], corners[i][1])));
    }

    private static Shape circle(ViewTransform view, Pose2D pose, double radiusMm) {
        double r = radiusMm * view.scale();
        return new Ellipse2D.Double(view.px(pose.x()) - r, view.py(pose.y()) - r, 2 * r, 2 * r);
    }
}
