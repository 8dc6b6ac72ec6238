package robosim.env.core;

import java.util.random.RandomGenerator;
import robosim.geometry.Angles;

/**
 * Where a robot believes it is: its true motion each step, plus drift when the world has odometry
 * noise. The drift is Gaussian with a standard deviation of {@code error} times the distance
 * travelled (per mm) and times the angle turned (per radian), drawn from the robot's own seeded
 * stream. Without noise the odometry is the true pose, exactly, until the robot is placed somewhere
 * else by the simulator: then it keeps following the true motion from where it was.
 */
final class Odometry {
    private final double error;
    private final RandomGenerator random;
    private double x;
    private double y;
    private double th;
    /** Without noise the odometry is the true pose turned by this and shifted by (dx, dy): a placement moves it. */
    private double dx;
    private double dy;
    private double dth;

    Odometry(double x, double y, double th, double error, RandomGenerator random) {
        this.x = x;
        this.y = y;
        this.th = th;
        this.error = error;
        this.random = random;
    }

    /**
     * Adds one step's motion.
     *
     * @param distance arc length travelled, mm
     * @param rotation heading change, radians
     * @param trueX    the true pose after it, used as it is when there is no noise
     * @param trueY    mm
     * @param trueTh   degrees
     */
    void travel(double distance, double rotation, double trueX, double trueY, double trueTh) {
        if (error == 0) {
            double a = Math.toRadians(dth);
            x = trueX * Math.cos(a) - trueY * Math.sin(a) + dx;
            y = trueX * Math.sin(a) + trueY * Math.cos(a) + dy;
            th = Angles.fix(trueTh + dth);
            return;
        }
        double d = distance + random.nextGaussian() * error * Math.abs(distance);
        double r = rotation + random.nextGaussian() * error * Math.abs(rotation);
        robosim.geometry.Pose2D p = new robosim.geometry.Pose2D(x, y, Math.toRadians(th)).advance(d, r);
        x = p.x();
        y = p.y();
        th = Angles.fix(Math.toDegrees(p.th()));
    }

    /**
     * The robot was put at a new true pose without moving (SIM_SET_POSE): the odometry stays where it
     * was, and from now on follows the true motion from there.
     */
    void placed(double trueX, double trueY, double trueTh) {
        dth = th - trueTh;
        double a = Math.toRadians(dth);
        dx = x - (trueX * Math.cos(a) - trueY * Math.sin(a));
        dy = y - (trueX * Math.sin(a) + trueY * Math.cos(a));
    }

    /** Sets the odometry to a pose, as at the start (SIM_RESET). */
    void reset(double newX, double newY, double newTh) {
        x = newX;
        y = newY;
        th = Angles.fix(newTh);
        dx = 0;
        dy = 0;
        dth = 0;
    }

    double x() {
        return x;
    }

    double y() {
        return y;
    }

    double th() {
        return th;
    }
}
