package robosim.aria;

/**
 * ARIA's pose: x and y in mm, heading in degrees normalised to (-180, 180] whenever it is set.
 */
public final class ArPose {
    private double x;
    private double y;
    private double th;

    /** The origin, heading 0. */
    public ArPose() {
        this(0, 0, 0);
    }

    /**
     * @param x  mm
     * @param y  mm
     * @param th degrees
     */
    public ArPose(double x, double y, double th) {
        setPose(x, y, th);
    }

    /**
     * @param x  mm
     * @param y  mm
     * @param th degrees
     */
    public void setPose(double x, double y, double th) {
        this.x = x;
        this.y = y;
        this.th = ArMath.fixAngle(th);
    }

    /** @return x, mm */
    public double getX() {
        return x;
    }

    /** @return y, mm */
    public double getY() {
        return y;
    }

    /** @return heading, degrees in (-180, 180] */
    public double getTh() {
        return th;
    }

    /** @param x mm */
    public void setX(double x) {
        this.x = x;
    }

    /** @param y mm */
    public void setY(double y) {
        this.y = y;
    }

    /** @param th degrees, normalised */
    public void setTh(double th) {
        this.th = ArMath.fixAngle(th);
    }

    /**
     * @param other another pose
     * @return the distance between the two positions, mm
     */
    public double findDistanceTo(ArPose other) {
        return Math.hypot(other.x - x, other.y - y);
    }

    /**
     * @param other another pose
     * @return the squared distance between the two positions, mm²
     */
    public double squaredFindDistanceTo(ArPose other) {
        double dx = other.x - x;
        double dy = other.y - y;
        return dx * dx + dy * dy;
    }

    /**
     * @param other another pose
     * @return the direction from this position to the other's, degrees (atan2)
     */
    public double findAngleTo(ArPose other) {
        return ArMath.fixAngle(Math.toDegrees(Math.atan2(other.y - y, other.x - x)));
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "ArPose(%.1f, %.1f, %.1f)", x, y, th);
    }
}
