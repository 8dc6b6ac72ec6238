package robosim.viewer.draw;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import robosim.geometry.Pose2D;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription.RobotInfo;
import robosim.protocol.RobotParameters;

/**
 * Draws a robot's latest laser scan as faint rays from the laser to each reading, with a dot where
 * a beam hit something, in any view: the caller says where a point of the ground lands on the
 * screen (the 2D view maps it flat; the 3D view draws the scan on the floor).
 *
 * <p>Reading {@code i} lies at {@code -90° + i * laserIncrement} from the laser's heading. The
 * laser sits at its mounting pose from the robot's parameters, carried by the robot's true pose
 * (the scan is of the real world, whatever the odometry believes). A robot the world does not
 * describe has its laser at its centre, facing forward.
 */
public final class LaserPainter {
    /** Opacity of the rays, 0 to 255: faint, so that scans do not hide the world. */
    static final int RAY_ALPHA = 60;
    /** Opacity of the dots where beams hit something, 0 to 255. */
    static final int HIT_ALPHA = 220;
    /** Side of the dot drawn where a beam hit something, px. */
    static final double HIT_PX = 2.5;

    private LaserPainter() {
    }

    /**
     * @param g        where to draw
     * @param toScreen the view's projection of the ground
     * @param robot    the robot, with its scan
     * @param info     the robot's parameters (where its laser sits), or null
     * @param colour   the robot's colour
     */
    public static void drawScan(Graphics2D g, TrailPainter.ToScreen toScreen, RobotView robot, RobotInfo info,
                                Color colour) {
        int[] ranges = robot.laser();
        double increment = robot.laserIncrement();
        if (ranges == null || ranges.length == 0 || !(increment > 0) || !Double.isFinite(increment)) {
            return;
        }
        RobotParameters p = info == null ? null : info.parameters();
        Pose2D robotPose = new Pose2D(robot.x(), robot.y(), Math.toRadians(robot.th()));
        double mountX = p == null ? 0 : p.laserX();
        double mountY = p == null ? 0 : p.laserY();
        double mountTh = p == null ? 0 : p.laserTh();
        double maxRange = p == null || !(p.laserMaxRange() > 0) ? Double.POSITIVE_INFINITY : p.laserMaxRange();
        double[] screen = new double[2];
        toScreen.map(robotPose.worldX(mountX, mountY), robotPose.worldY(mountX, mountY), screen);
        double ox = screen[0];
        double oy = screen[1];
        // One path for all rays: drawn at once, overlapping rays do not darken near the laser.
        Path2D.Double rays = new Path2D.Double();
        Path2D.Double hits = new Path2D.Double();
        for (int i = 0; i < ranges.length; i++) {
            if (ranges[i] <= 0) {
                continue;
            }
            double heading = Math.toRadians(mountTh - 90 + i * increment);
            double endX = mountX + ranges[i] * Math.cos(heading);
            double endY = mountY + ranges[i] * Math.sin(heading);
            toScreen.map(robotPose.worldX(endX, endY), robotPose.worldY(endX, endY), screen);
            double x = screen[0];
            double y = screen[1];
            rays.moveTo(ox, oy);
            rays.lineTo(x, y);
            if (ranges[i] < maxRange) {
                hits.append(new Rectangle2D.Double(x - HIT_PX / 2, y - HIT_PX / 2, HIT_PX, HIT_PX), false);
            }
        }
        g.setStroke(new BasicStroke(1f));
        g.setColor(withAlpha(colour, RAY_ALPHA));
        g.draw(rays);
        g.setColor(withAlpha(colour, HIT_ALPHA));
        g.fill(hits);
    }

    private static Color withAlpha(Color c, int alpha) {
        return new Color(c.getRed(), c.getGreen(), c.getBlue(), alpha);
    }
}
