package robosim.scout;

/**
 * The frame the Nomad's configuration is reported in: a rigid transform of the Environment's
 * odometry, which {@link Scout#zr}, {@link Scout#dp} and {@link Scout#da} redefine. Redefining the
 * pose moves the frame, not the robot, so the odometry goes on integrating from the new values as
 * the real robot's does.
 */
final class PoseFrame {
    private double turn;
    private double dx;
    private double dy;

    /**
     * @param x  odometry x, mm
     * @param y  odometry y, mm
     * @param th odometry heading, degrees
     * @return the pose in this frame: x, y (mm), heading (degrees, not normalised)
     */
    double[] apply(double x, double y, double th) {
        double a = Math.toRadians(turn);
        double c = Math.cos(a);
        double s = Math.sin(a);
        return new double[] {c * x - s * y + dx, s * x + c * y + dy, th + turn};
    }

    /**
     * Makes a pose read (0, 0, 0).
     *
     * @param x  odometry x, mm
     * @param y  odometry y, mm
     * @param th odometry heading, degrees
     */
    void zero(double x, double y, double th) {
        turn = -th;
        place(x, y, 0, 0);
    }

    /**
     * Makes a pose read at a position, its heading unchanged.
     *
     * @param x    odometry x, mm
     * @param y    odometry y, mm
     * @param newX the position it reads, mm
     * @param newY the position it reads, mm
     */
    void definePosition(double x, double y, double newX, double newY) {
        place(x, y, newX, newY);
    }

    /**
     * Makes a pose read a heading, its position unchanged.
     *
     * @param x     odometry x, mm
     * @param y     odometry y, mm
     * @param th    odometry heading, degrees
     * @param newTh the heading it reads, degrees
     */
    void defineHeading(double x, double y, double th, double newTh) {
        double[] now = apply(x, y, th);
        turn = newTh - th;
        place(x, y, now[0], now[1]);
    }

    private void place(double x, double y, double newX, double newY) {
        dx = 0;
        dy = 0;
        double[] rotated = apply(x, y, 0);
        dx = newX - rotated[0];
        dy = newY - rotated[1];
    }
}
