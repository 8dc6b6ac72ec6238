package robosim.env.core;

import java.util.random.RandomGenerator;

/**
 * Where a robot believes it is: its true motion each step, plus drift when the world has odometry
 * noise. The drift is Gaussian with a standard deviation of {@code error} times the distance
 * travelled (per mm) and times the angle turned (per radian), drawn from the robot's own seeded
 * stream. Without noise the odometry is the true pose, exactly.
 */
final class Odometry {
    private final double error;
    private final RandomGenerator random;
    private double x;
    private double y;
    private double th;

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
            x = trueX;
            y = trueY;
            th = trueTh;
            return;
        }
        double d = distance + random.nextGaussian() * error * Math.abs(distance);
        double r = rotation + random.nextGaussian() * error * Math.abs(rotation);
        robosim.geometry.Pose2D p = new robosim.geometry.Pose2D(x, y, Math.toRadians(th)).advance(d, r);
        x = p.x();
        y = p.y();
        th = Angles.fix(Math.toDegrees(p.th()));
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
