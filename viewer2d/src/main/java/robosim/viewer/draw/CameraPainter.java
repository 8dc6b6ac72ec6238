package robosim.viewer.draw;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Path2D;
import robosim.protocol.Snapshot.RobotView;

/**
 * Draws a robot's camera, while it is on, as the two dashed edges of its horizontal field of view
 * from the robot's centre, {@value #REACH_MM} mm long, along its heading turned by the pan
 * (positive to the right, as ARIA's). The {@link WorldRenderer}'s helper.
 */
final class CameraPainter {
    /** The dashed edges' stroke. */
    private static final BasicStroke EDGE =
            new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f);
    /** How far the edges reach, mm. */
    static final double REACH_MM = 1500;
    /** Opacity of the edges, 0 to 255. */
    static final int ALPHA = 160;

    void drawFieldOfView(Graphics2D g, ViewTransform view, RobotView robot, Color colour) {
        double[] camera = robot.camera();
        if (camera == null || camera.length < 2 || !Double.isFinite(camera[0]) || !(camera[1] > 0)) {
            return;
        }
        double axis = Math.toRadians(robot.th() - camera[0]);
        double half = Math.toRadians(camera[1] / 2);
        double ox = view.px(robot.x());
        double oy = view.py(robot.y());
        Path2D.Double edges = new Path2D.Double();
        for (double a : new double[] {axis - half, axis + half}) {
            edges.moveTo(ox, oy);
            edges.lineTo(view.px(robot.x() + REACH_MM * Math.cos(a)), view.py(robot.y() + REACH_MM * Math.sin(a)));
        }
        g.setStroke(EDGE);
        g.setColor(new Color(colour.getRed(), colour.getGreen(), colour.getBlue(), ALPHA));
        g.draw(edges);
    }
}
