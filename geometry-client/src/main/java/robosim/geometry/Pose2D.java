package robosim.geometry;

/**
 * A pose in the world plane: position in mm and heading in radians, counter-clockwise from +x.
 *
 * @param x  mm
 * @param y  mm
 * @param th heading in radians
 */
public record Pose2D(double x, double y, double th) {

    /**
     * The pose reached by travelling {@code distance} along a path of constant curvature while
     * turning by {@code rotation}: the exact motion of a differential drive holding its wheel speeds.
     *
     * @param distance arc length in mm, negative backwards
     * @param rotation change of heading in radians
     * @return the pose at the end of the arc
     */
    public Pose2D advance(double distance, double rotation) {
        if (Math.abs(rotation) < 1e-12) {
            return new Pose2D(x + distance * Math.cos(th), y + distance * Math.sin(th), th);
        }
        double r = distance / rotation;
        double th1 = th + rotation;
        return new Pose2D(x + r * (Math.sin(th1) - Math.sin(th)), y - r * (Math.cos(th1) - Math.cos(th)), th1);
    }

    /**
     * @param localX mm forward in this pose's frame
     * @param localY mm left in this pose's frame
     * @return the world x of that point
     */
    public double worldX(double localX, double localY) {
        return x + localX * Math.cos(th) - localY * Math.sin(th);
    }

    /**
     * @param localX mm forward in this pose's frame
     * @param localY mm left in this pose's frame
     * @return the world y of that point
     */
    public double worldY(double localX, double localY) {
        return y + localX * Math.sin(th) + localY * Math.cos(th);
    }
}
