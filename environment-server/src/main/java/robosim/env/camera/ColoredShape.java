package robosim.env.camera;

/**
 * A thing the camera can see: a polygon standing on the floor up to a height, with a colour or
 * none. Uncoloured things (walls without a colour, robots) hide what is behind them but never
 * belong to a channel.
 */
public final class ColoredShape {
    /** The colour of a shape that has none. */
    public static final int NO_COLOR = -1;

    private final double[] xy;
    private final double height;
    private final int rgb;
    private final int owner;
    private final double minX;
    private final double maxX;
    private final double minY;
    private final double maxY;

    /**
     * @param xy     its outline x0, y0, x1, y1, ... in mm, not closed
     * @param height mm above the floor
     * @param rgb    its colour as 0xrrggbb, or {@link #NO_COLOR}
     * @param owner  the robot body it is, which that robot's own camera does not see; −1 for none
     */
    public ColoredShape(double[] xy, double height, int rgb, int owner) {
        if (xy.length < 6 || xy.length % 2 != 0) {
            throw new IllegalArgumentException("a shape needs at least 3 x,y points, not " + xy.length + " numbers");
        }
        if (!(height > 0)) {
            throw new IllegalArgumentException(height + " was supplied for a shape's height: it must be greater than 0");
        }
        this.xy = xy.clone();
        this.height = height;
        this.rgb = rgb;
        this.owner = owner;
        double x0 = Double.POSITIVE_INFINITY;
        double x1 = Double.NEGATIVE_INFINITY;
        double y0 = Double.POSITIVE_INFINITY;
        double y1 = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < xy.length; i += 2) {
            x0 = Math.min(x0, xy[i]);
            x1 = Math.max(x1, xy[i]);
            y0 = Math.min(y0, xy[i + 1]);
            y1 = Math.max(y1, xy[i + 1]);
        }
        minX = x0;
        maxX = x1;
        minY = y0;
        maxY = y1;
    }

    /** @return mm above the floor */
    public double height() {
        return height;
    }

    /** @return its colour as 0xrrggbb, or {@link #NO_COLOR} */
    public int rgb() {
        return rgb;
    }

    /** @return the robot body it is, or −1 */
    public int owner() {
        return owner;
    }

    /** @return whether any of it lies within {@code range} of (x, y) by its bounding box */
    boolean near(double x, double y, double range) {
        double dx = Math.max(0, Math.max(minX - x, x - maxX));
        double dy = Math.max(0, Math.max(minY - y, y - maxY));
        return dx * dx + dy * dy <= range * range;
    }

    /**
     * Whether some of the shape's bounding box may lie within a wedge from (x, y): a cheap test
     * that lets a camera skip what is outside its field of view. It errs towards yes.
     *
     * @param direction the wedge's axis, radians
     * @param half      its half angle, radians, below π/2
     */
    boolean mayBeWithin(double x, double y, double direction, double half) {
        if (x >= minX && x <= maxX && y >= minY && y <= maxY) {
            return true;
        }
        double low = Double.POSITIVE_INFINITY;
        double high = Double.NEGATIVE_INFINITY;
        double[] cx = {minX, maxX, maxX, minX};
        double[] cy = {minY, minY, maxY, maxY};
        for (int i = 0; i < 4; i++) {
            double a = Math.IEEEremainder(Math.atan2(cy[i] - y, cx[i] - x) - direction, 2 * Math.PI);
            low = Math.min(low, a);
            high = Math.max(high, a);
        }
        // a box seen from outside spans less than π; a wider spread means it wraps round behind the camera
        if (high - low > Math.PI) {
            return true;
        }
        return high >= -half && low <= half;
    }

    /**
     * @return the distance along the ray from (x, y) in direction (dx, dy), a unit vector, to where
     *         it first crosses the outline; infinity if it does not
     */
    double hit(double x, double y, double dx, double dy) {
        double best = Double.POSITIVE_INFINITY;
        int n = xy.length;
        for (int i = 0; i < n; i += 2) {
            double ax = xy[i];
            double ay = xy[i + 1];
            double ex = xy[(i + 2) % n] - ax;
            double ey = xy[(i + 3) % n] - ay;
            double denom = dx * ey - dy * ex;
            if (denom == 0) {
                continue;
            }
            double wx = ax - x;
            double wy = ay - y;
            double t = (wx * ey - wy * ex) / denom;
            double s = (wx * dy - wy * dx) / denom;
            if (t > 0 && s >= 0 && s <= 1 && t < best) {
                best = t;
            }
        }
        return best;
    }
}
