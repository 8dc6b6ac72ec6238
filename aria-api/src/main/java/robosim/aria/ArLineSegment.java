package robosim.aria;

import java.util.Locale;

/**
 * ARIA's {@code ArLineSegment} (ariaUtil.h): a segment between two end points, with the infinite
 * line through them kept as {@code a·x + b·y = c} (ARIA's {@code ArLine}: a = y1 − y2,
 * b = x2 − x1, c = x2·y1 − y2·x1). A map's lines ({@link ArMap#getLines()}) and a forbidden area's
 * sides ({@link ArMapObject#getFromToSegments()}) are segments. Distances in mm.
 */
public class ArLineSegment implements Comparable<ArLineSegment> {
    /** Below this, ARIA's {@code ArLine::intersects} takes two lines for parallel. */
    private static final double PARALLEL = 1e-13;

    private double x1;
    private double y1;
    private double x2;
    private double y2;
    private double a;
    private double b;
    private double c;

    /** A segment from (0, 0) to (0, 0). */
    public ArLineSegment() {
        newEndPoints(0, 0, 0, 0);
    }

    /**
     * @param x1 the first end's x, mm
     * @param y1 the first end's y, mm
     * @param x2 the second end's x, mm
     * @param y2 the second end's y, mm
     */
    public ArLineSegment(double x1, double y1, double x2, double y2) {
        newEndPoints(x1, y1, x2, y2);
    }

    /**
     * @param pose1 the first end (its heading is not used)
     * @param pose2 the second end
     */
    public ArLineSegment(ArPose pose1, ArPose pose2) {
        newEndPoints(pose1.getX(), pose1.getY(), pose2.getX(), pose2.getY());
    }

    /**
     * Moves the ends, as ARIA's {@code newEndPoints}.
     *
     * @param x1 the first end's x, mm
     * @param y1 the first end's y, mm
     * @param x2 the second end's x, mm
     * @param y2 the second end's y, mm
     */
    public void newEndPoints(double x1, double y1, double x2, double y2) {
        this.x1 = x1;
        this.y1 = y1;
        this.x2 = x2;
        this.y2 = y2;
        a = y1 - y2;
        b = x2 - x1;
        c = x2 * y1 - y2 * x1;
    }

    /**
     * Moves the ends.
     *
     * @param pt1 the first end
     * @param pt2 the second end
     */
    public void newEndPoints(ArPose pt1, ArPose pt2) {
        newEndPoints(pt1.getX(), pt1.getY(), pt2.getX(), pt2.getY());
    }

    /** @return the first end, heading 0 */
    public ArPose getEndPoint1() {
        return new ArPose(x1, y1);
    }

    /** @return the second end, heading 0 */
    public ArPose getEndPoint2() {
        return new ArPose(x2, y2);
    }

    /**
     * Whether this segment and another cross, as ARIA's {@code intersects(const ArLineSegment&, ArPose*)}:
     * the two infinite lines meet (they are not parallel) at a point inside both segments.
     *
     * @param line the other segment
     * @param pose set to the crossing when there is one; may be null
     * @return whether they cross
     */
    public boolean intersects(ArLineSegment line, ArPose pose) {
        ArPose p = lineCrossing(line.a, line.b, line.c);
        if (p == null || !linePointIsInSegment(p) || !line.linePointIsInSegment(p)) {
            return false;
        }
        if (pose != null) {
            pose.setPose(p.getX(), p.getY());
        }
        return true;
    }

    /**
     * @param line the other segment
     * @return whether they cross, as {@link #intersects(ArLineSegment, ArPose)}
     */
    public boolean intersects(ArLineSegment line) {
        return intersects(line, null);
    }

    /**
     * Projects a point onto this segment, as ARIA's {@code getPerpPoint}: the foot of the
     * perpendicular through the point, if it lies inside the segment.
     *
     * @param pose      the point
     * @param perpPoint set to the foot when it lies inside the segment
     * @return whether it does
     */
    public boolean getPerpPoint(ArPose pose, ArPose perpPoint) {
        ArPose foot = foot(pose);
        if (foot == null || !linePointIsInSegment(foot)) {
            return false;
        }
        perpPoint.setPose(foot.getX(), foot.getY());
        return true;
    }

    /**
     * @param pose a point
     * @return the distance from the point to its foot on this segment, or −1 when the foot is
     *         outside the segment (ARIA's {@code getPerpDist})
     */
    public double getPerpDist(ArPose pose) {
        ArPose foot = foot(pose);
        return foot == null || !linePointIsInSegment(foot) ? -1 : foot.findDistanceTo(pose);
    }

    /**
     * @param pose a point
     * @return the squared distance to its foot on this segment, or −1 when the foot is outside it
     *         (ARIA's {@code getPerpSquaredDist})
     */
    public double getPerpSquaredDist(ArPose pose) {
        ArPose foot = foot(pose);
        return foot == null || !linePointIsInSegment(foot) ? -1 : foot.squaredFindDistanceTo(pose);
    }

    /**
     * The distance from a point to the infinite line through this segment, as ARIA's
     * {@code getDistToLine}: for a segment of one point (no line), the distance to the nearer end,
     * rounded to a whole mm as ARIA rounds it.
     *
     * @param pose a point
     * @return mm
     */
    public double getDistToLine(ArPose pose) {
        ArPose foot = foot(pose);
        if (foot == null) {
            return Math.min(ArMath.roundInt(getEndPoint1().findDistanceTo(pose)),
                    ArMath.roundInt(getEndPoint2().findDistanceTo(pose)));
        }
        return foot.findDistanceTo(pose);
    }

    /** @return the segment's length, mm */
    public double getLengthOf() {
        return ArMath.distanceBetween(x1, y1, x2, y2);
    }

    /** @return the point half way between the ends, heading 0 */
    public ArPose getMidPoint() {
        return new ArPose((x1 + x2) / 2.0, (y1 + y2) / 2.0, 0);
    }

    /** @return the first end's x, mm */
    public double getX1() {
        return x1;
    }

    /** @return the first end's y, mm */
    public double getY1() {
        return y1;
    }

    /** @return the second end's x, mm */
    public double getX2() {
        return x2;
    }

    /** @return the second end's y, mm */
    public double getY2() {
        return y2;
    }

    /** @return the line's a: y1 − y2 */
    public double getA() {
        return a;
    }

    /** @return the line's b: x2 − x1 */
    public double getB() {
        return b;
    }

    /** @return the line's c: x2·y1 − y2·x1 */
    public double getC() {
        return c;
    }

    /**
     * Whether a point known to lie on the line lies between the ends, as ARIA's
     * {@code linePointIsInSegment}: checked along x unless the segment is vertical and along y
     * unless it is horizontal; a segment of one point holds only that point.
     *
     * @param pose a point on the line
     * @return whether it is inside the segment
     */
    public boolean linePointIsInSegment(ArPose pose) {
        boolean vertical = Math.abs(x1 - x2) < ArMath.epsilon();
        boolean horizontal = Math.abs(y1 - y2) < ArMath.epsilon();
        double x = pose.getX();
        double y = pose.getY();
        if (vertical && horizontal) {
            return Math.abs(x1 - x) < ArMath.epsilon() && Math.abs(y1 - y) < ArMath.epsilon();
        }
        return (vertical || x >= x1 && x <= x2 || x <= x1 && x >= x2)
                && (horizontal || y >= y1 && y <= y2 || y <= y1 && y >= y2);
    }

    /** @return where the infinite line through this segment meets the perpendicular through the point, or null */
    private ArPose foot(ArPose pose) {
        // ARIA's ArLine::perpendicularLine: (-b, a, a*y - b*x)
        return lineCrossing(-b, a, a * pose.getY() - b * pose.getX());
    }

    /** @return where this segment's infinite line meets the line la·x + lb·y = lc, or null if parallel */
    private ArPose lineCrossing(double la, double lb, double lc) {
        return crossing(a, b, c, la, lb, lc);
    }

    /**
     * Where two infinite lines a·x + b·y = c cross, as ARIA 2.x's {@code ArLine::intersects}
     * (ariaUtil.h). AriaCoda's has {@code line.getA()} for {@code line.getB()} in x, a slip of its
     * refactoring that puts the crossing off the lines for most lines that miss the origin; RoboSim
     * keeps ARIA 2.x's.
     *
     * @return the point, heading 0, or null if they are parallel
     */
    static ArPose crossing(double a1, double b1, double c1, double a2, double b2, double c2) {
        double n = -(b2 * a1 - a2 * b1);
        if (Math.abs(n) < PARALLEL) {
            return null;
        }
        return new ArPose((c2 * b1 - b2 * c1) / n, (c1 * a2 - a1 * c2) / n, 0);
    }

    /** Equal ends, each within {@link ArMath#epsilon()}, as ARIA's {@code operator==}. */
    @Override
    public boolean equals(Object o) {
        return o instanceof ArLineSegment s && Math.abs(x1 - s.x1) < ArMath.epsilon()
                && Math.abs(y1 - s.y1) < ArMath.epsilon() && Math.abs(x2 - s.x2) < ArMath.epsilon()
                && Math.abs(y2 - s.y2) < ArMath.epsilon();
    }

    @Override
    public int hashCode() {
        // equal segments may differ by less than epsilon: only whole mm go into the hash
        return Long.hashCode(Math.round(x1) * 31 + Math.round(y1)) * 31 + Long.hashCode(Math.round(x2) * 31 + Math.round(y2));
    }

    /** Orders by x1, then y1, then x2, then y2, each compared beyond {@link ArMath#epsilon()}, as ARIA's {@code operator<}. */
    @Override
    public int compareTo(ArLineSegment o) {
        double[] mine = {x1, y1, x2, y2};
        double[] theirs = {o.x1, o.y1, o.x2, o.y2};
        for (int i = 0; i < mine.length; i++) {
            if (Math.abs(mine[i] - theirs[i]) > ArMath.epsilon()) {
                return mine[i] < theirs[i] ? -1 : 1;
            }
        }
        return 0;
    }

    /** @return {@code (x1, y1, x2, y2)}, as ARIA's {@code toString} writes it */
    @Override
    public String toString() {
        return String.format(Locale.ROOT, "(%f, %f, %f, %f)", x1, y1, x2, y2);
    }
}
