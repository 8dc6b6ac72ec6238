package robosim.pioneer.server;

/**
 * The robot's own odometry frame, as a Pioneer reports it: (0, 0, 0) where the client connected or
 * last reset it with SETO, whatever the robot's pose in the world. Holds the Environment's
 * odometry pose at that moment and turns the Environment's poses into the robot's and back. Safe to
 * use from the client's thread and the robot's.
 */
final class OdometryFrame {
    private double originX;
    private double originY;
    private double originTh;

    /**
     * Makes a pose the new origin.
     *
     * @param x  the Environment's odometry x, mm
     * @param y  mm
     * @param th degrees
     */
    synchronized void resetAt(double x, double y, double th) {
        originX = x;
        originY = y;
        originTh = th;
    }

    /**
     * @param x  the Environment's odometry x, mm
     * @param y  mm
     * @param th degrees
     * @return the pose in the robot's frame: x, y in mm, th in degrees within (−180, 180]
     */
    synchronized double[] toRobot(double x, double y, double th) {
        double a = Math.toRadians(-originTh);
        double dx = x - originX;
        double dy = y - originY;
        return new double[] {dx * Math.cos(a) - dy * Math.sin(a), dx * Math.sin(a) + dy * Math.cos(a),
                fix(th - originTh)};
    }

    /**
     * @param heading a heading in the robot's frame, degrees
     * @return the same heading in the Environment's odometry frame
     */
    synchronized double toEnvironmentHeading(double heading) {
        return fix(heading + originTh);
    }

    static double fix(double degrees) {
        double a = Math.IEEEremainder(degrees, 360);
        return a <= -180 ? a + 360 : a;
    }
}
