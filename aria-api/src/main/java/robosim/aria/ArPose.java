package robosim.aria;

import java.util.List;

/**
 * ARIA's pose ({@code ArPose}, ariaUtil.h): x and y in mm, heading in degrees normalised to
 * (-180, 180] whenever it is set. ARIA's operators are methods here: {@code +} is {@link #add},
 * {@code -} {@link #subtract}, {@code +=} {@link #addInPlace}, {@code -=} {@link #subtractInPlace},
 * {@code ==} {@link #isEqual}, {@code !=} {@link #isNotEqual}, {@code <} {@link #isLessThan}.
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
     * As ARIA's constructor with th left at its default 0.
     *
     * @param x mm
     * @param y mm
     */
    public ArPose(double x, double y) {
        this(x, y, 0);
    }

    /**
     * A copy (ARIA's copy constructor).
     *
     * @param other the pose copied
     */
    public ArPose(ArPose other) {
        this(other.x, other.y, other.th);
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

    /**
     * As ARIA's {@code setPose(x, y)}: the heading's default is 0, so it is set to 0.
     *
     * @param x mm
     * @param y mm
     */
    public void setPose(double x, double y) {
        setPose(x, y, 0);
    }

    /**
     * As ARIA's {@code setPose(const ArPose&)}.
     *
     * @param position the pose copied into this one
     */
    public void setPose(ArPose position) {
        setPose(position.x, position.y, position.th);
    }

    /**
     * As ARIA's {@code setThRad}.
     *
     * @param th the heading in radians, normalised to (-180, 180] degrees
     */
    public void setThRad(double th) {
        this.th = ArMath.fixAngle(ArMath.radToDeg(th));
    }

    /** @return the heading in radians (ARIA's {@code getThRad}) */
    public double getThRad() {
        return ArMath.degToRad(th);
    }

    /**
     * ARIA's {@code getPose(double *x, double *y, double *th)}, with one-element arrays for the
     * pointers: each that is not null receives its value.
     *
     * @param x  null, or an array whose element 0 receives x
     * @param y  null, or an array whose element 0 receives y
     * @param th null, or an array whose element 0 receives the heading
     */
    public void getPose(double[] x, double[] y, double[] th) {
        if (x != null) {
            x[0] = this.x;
        }
        if (y != null) {
            y[0] = this.y;
        }
        if (th != null) {
            th[0] = this.th;
        }
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
     * @return the direction from this position to the other's, degrees (atan2), normalised to
     *         (-180, 180] (ARIA's own answer is atan2's, which can be -180 exactly); 0 to the same position
     */
    public double findAngleTo(ArPose other) {
        return ArMath.fixAngle(Math.toDegrees(Math.atan2(other.y - y, other.x - x)));
    }

    /** Logs the pose with {@link ArLog} at {@code Terse}, as ARIA's {@code log()}: {@code "%.0f %.0f %.1f"}. */
    public void log() {
        ArLog.log(ArLog.Terse, "%.0f %.0f %.1f", x, y, th);
    }

    /**
     * ARIA's {@code operator+}.
     *
     * @param other a pose
     * @return a new pose: the sums of the x, the y and the headings (normalised)
     */
    public ArPose add(ArPose other) {
        return new ArPose(x + other.x, y + other.y, th + other.th);
    }

    /**
     * ARIA's {@code operator-}.
     *
     * @param other a pose
     * @return a new pose: the differences of the x, the y and the headings (normalised)
     */
    public ArPose subtract(ArPose other) {
        return new ArPose(x - other.x, y - other.y, th - other.th);
    }

    /**
     * ARIA's {@code operator+=}.
     *
     * @param other a pose added to this one
     * @return this pose
     */
    public ArPose addInPlace(ArPose other) {
        setPose(x + other.x, y + other.y, th + other.th);
        return this;
    }

    /**
     * ARIA's {@code operator-=}.
     *
     * @param other a pose subtracted from this one
     * @return this pose
     */
    public ArPose subtractInPlace(ArPose other) {
        setPose(x - other.x, y - other.y, th - other.th);
        return this;
    }

    /**
     * ARIA's {@code operator==}: each of x, y and the heading differs by less than
     * {@link ArMath#epsilon()}. (Not {@link #equals}, which is exact, as Java's contract with
     * {@code hashCode} needs.)
     *
     * @param other a pose
     * @return whether the two are equal by ARIA's rule
     */
    public boolean isEqual(ArPose other) {
        double e = ArMath.epsilon();
        return ArMath.fabs(x - other.x) < e && ArMath.fabs(y - other.y) < e && ArMath.fabs(th - other.th) < e;
    }

    /**
     * ARIA's {@code operator!=}: some component differs by more than {@link ArMath#epsilon()}. As in
     * ARIA, a difference of exactly epsilon is neither equal nor unequal.
     *
     * @param other a pose
     * @return whether the two differ by ARIA's rule
     */
    public boolean isNotEqual(ArPose other) {
        double e = ArMath.epsilon();
        return ArMath.fabs(x - other.x) > e || ArMath.fabs(y - other.y) > e || ArMath.fabs(th - other.th) > e;
    }

    /**
     * ARIA's {@code operator<}: by x, then y, then heading, each compared only when it differs by more
     * than {@link ArMath#epsilon()}.
     *
     * @param other a pose
     * @return whether this pose sorts before the other
     */
    public boolean isLessThan(ArPose other) {
        double e = ArMath.epsilon();
        if (ArMath.fabs(x - other.x) > e) {
            return x < other.x;
        }
        if (ArMath.fabs(y - other.y) > e) {
            return y < other.y;
        }
        if (ArMath.fabs(th - other.th) > e) {
            return th < other.th;
        }
        return false;
    }

    /**
     * As ARIA's static {@code ArPose::distanceBetween}.
     *
     * @param pose1 a pose
     * @param pose2 another
     * @return the distance between their positions, mm
     */
    public static double distanceBetween(ArPose pose1, ArPose pose2) {
        return ArMath.distanceBetween(pose1.x, pose1.y, pose2.x, pose2.y);
    }

    /**
     * As ARIA's {@code ArPose::compareX}, a sort predicate.
     *
     * @param p1 a pose
     * @param p2 another
     * @return whether p1's x is less than p2's
     */
    public static boolean compareX(ArPose p1, ArPose p2) {
        return p1.x < p2.x;
    }

    /**
     * As ARIA's {@code ArPose::compareY}, a sort predicate.
     *
     * @param p1 a pose
     * @param p2 another
     * @return whether p1's y is less than p2's
     */
    public static boolean compareY(ArPose p1, ArPose p2) {
        return p1.y < p2.y;
    }

    /**
     * As ARIA's {@code isInsidePolygon} (ariaUtil.h): the even-odd rule, by crossings of a ray from
     * this position towards +x; the vertices in order, the last joined to the first; headings ignored.
     * Points on the boundary fall as ARIA's test makes them fall (it is kept as it is, degenerate
     * polygons included); no vertices hold nothing.
     *
     * @param vertices the polygon's corners
     * @return whether this position is inside
     */
    public boolean isInsidePolygon(List<ArPose> vertices) {
        boolean inside = false;
        int n = vertices.size();
        for (int i = 0, j = n - 1; i < n; j = i++) {
            double x1 = vertices.get(i).x;
            double y1 = vertices.get(i).y;
            double x2 = vertices.get(j).x;
            double y2 = vertices.get(j).y;
            boolean spans = (y1 < y && y < y2) || (y2 <= y && y < y1);
            if (spans && x <= (x2 - x1) * (y - y1) / (y2 - y1) + x1) {
                inside = !inside;
            }
        }
        return inside;
    }

    /**
     * Exact equality of x, y and heading (0.0 and -0.0 equal), consistent with {@link #hashCode()};
     * ARIA's {@code ==} with its epsilon is {@link #isEqual}.
     */
    @Override
    public boolean equals(Object o) {
        return o instanceof ArPose p && bits(p.x) == bits(x) && bits(p.y) == bits(y) && bits(p.th) == bits(th);
    }

    @Override
    public int hashCode() {
        return java.util.Objects.hash(bits(x), bits(y), bits(th));
    }

    /** @return the value's bits, with -0.0 taken as 0.0 and every NaN as one */
    private static long bits(double v) {
        return Double.doubleToLongBits(v + 0.0);
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "ArPose(%.1f, %.1f, %.1f)", x, y, th);
    }
}
