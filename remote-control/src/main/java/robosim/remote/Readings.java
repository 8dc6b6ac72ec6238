package robosim.remote;

import java.util.ArrayList;
import java.util.List;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/**
 * One step's readings of the robot, as its own sensors give them, with the sonar rays and laser
 * hits placed in the robot's frame (x forward, y left, mm) for the polar plot. Made on the robot's
 * thread each step and handed whole to the window, so the window never reads a half-updated robot.
 *
 * @param step     the step
 * @param timeMs   simulated time, ms
 * @param x        odometry x, mm
 * @param y        odometry y, mm
 * @param th       odometry heading, degrees
 * @param vel      translational velocity, mm/s
 * @param rotVel   rotational velocity, deg/s
 * @param stalled  whether a collision stopped it
 * @param sonarOn  whether the sonars fire
 * @param sonar    the sonar rays, robot frame; empty when off
 * @param laserOn  whether the laser scans
 * @param laser    the laser's hits short of its maximum range, robot frame
 * @param heat     the heat reading, or null when the heat sensor is off
 * @param range    the plot's radius: the longest of the sonar's and laser's maximum ranges, mm
 */
public record Readings(long step, long timeMs, double x, double y, double th, double vel, double rotVel,
                       boolean stalled, boolean sonarOn, List<Ray> sonar, boolean laserOn, List<Point> laser,
                       Heat heat, double range) {
    /**
     * A point in the robot's frame.
     *
     * @param x mm forward
     * @param y mm left
     */
    public record Point(double x, double y) { }

    /**
     * A sonar's ray in the robot's frame, from the transducer to the echo.
     *
     * @param from  the transducer
     * @param to    the echo (or the maximum range when nothing echoed)
     * @param range mm from the transducer
     */
    public record Ray(Point from, Point to, int range) { }

    /**
     * What the heat sensor feels.
     *
     * @param intensity the strongest felt intensity, 0 when nothing is in view
     * @param bearing   degrees relative to the heading
     * @param distance  mm
     */
    public record Heat(double intensity, double bearing, double distance) { }

    /** Copies the lists, so a reading never changes after it is made. */
    public Readings {
        sonar = List.copyOf(sonar);
        laser = List.copyOf(laser);
    }

    /**
     * @param p      the robot's parameters (the sonars' mountings)
     * @param ranges each sonar's range, mm from its transducer, by index; a negative range is skipped
     * @return the rays
     */
    public static List<Ray> sonarRays(RobotParameters p, int[] ranges) {
        List<Ray> rays = new ArrayList<>();
        for (SonarUnit u : p.sonarUnits()) {
            int i = u.index();
            if (i < 0 || i >= ranges.length || ranges[i] < 0) {
                continue;
            }
            double a = Math.toRadians(u.th());
            rays.add(new Ray(new Point(u.x(), u.y()),
                    new Point(u.x() + ranges[i] * Math.cos(a), u.y() + ranges[i] * Math.sin(a)), ranges[i]));
        }
        return rays;
    }

    /**
     * @param p        the robot's parameters (the laser's mounting)
     * @param scan     the scan's ranges, mm from the laser, from its right to its left over 180°
     * @param maxRange the laser's maximum range: readings at or past it hit nothing
     * @return the hits
     */
    public static List<Point> laserHits(RobotParameters p, int[] scan, double maxRange) {
        List<Point> hits = new ArrayList<>();
        double step = scan.length > 1 ? 180.0 / (scan.length - 1) : 0;
        for (int i = 0; i < scan.length; i++) {
            if (scan[i] <= 0 || scan[i] >= maxRange) {
                continue;
            }
            double a = Math.toRadians(p.laserTh() - 90 + i * step);
            hits.add(new Point(p.laserX() + scan[i] * Math.cos(a), p.laserY() + scan[i] * Math.sin(a)));
        }
        return hits;
    }

    /** @return the shortest sonar range, or -1 with none */
    public int nearestSonar() {
        return sonar.stream().mapToInt(Ray::range).min().orElse(-1);
    }
}
