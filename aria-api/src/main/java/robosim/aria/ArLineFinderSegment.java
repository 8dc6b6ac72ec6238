package robosim.aria;

/**
 * A line found in a laser scan, as ARIA's {@code ArLineFinderSegment} (ArLineFinder.h): its end
 * points, its angle and length, how many scan points it covers (first and last by number) and their
 * average distance from it. ARIA's extends {@code ArLineSegment}; RoboSim's keeps the few line calls
 * it needs here, its crossings from {@link ArLineSegment}'s: {@link #getDistToLine} is ARIA's
 * (AriaCoda's): the distance from the infinite line through the end points.
 */
public class ArLineFinderSegment {
    private double x1, y1, x2, y2;
    private double lineAngle;
    private double length;
    private int numPoints;
    private int startPoint;
    private int endPoint;
    private double aveDistFromLine;

    /** A segment from the origin to the origin. */
    public ArLineFinderSegment() {
        this(0, 0, 0, 0);
    }

    /**
     * @param x1 first end's x, mm
     * @param y1 first end's y, mm
     * @param x2 second end's x, mm
     * @param y2 second end's y, mm
     */
    public ArLineFinderSegment(double x1, double y1, double x2, double y2) {
        this(x1, y1, x2, y2, 0, 0, 0);
    }

    /**
     * @param x1         first end's x, mm
     * @param y1         first end's y, mm
     * @param x2         second end's x, mm
     * @param y2         second end's y, mm
     * @param numPoints  how many scan points it covers
     * @param startPoint the first point's number
     * @param endPoint   the last point's number
     */
    public ArLineFinderSegment(double x1, double y1, double x2, double y2, int numPoints, int startPoint,
            int endPoint) {
        newEndPoints(x1, y1, x2, y2, numPoints, startPoint, endPoint);
    }

    /** @param other a segment to copy */
    public ArLineFinderSegment(ArLineFinderSegment other) {
        newEndPoints(other.x1, other.y1, other.x2, other.y2, other.numPoints, other.startPoint, other.endPoint);
        aveDistFromLine = other.aveDistFromLine;
    }

    /**
     * @param x1         first end's x, mm
     * @param y1         first end's y, mm
     * @param x2         second end's x, mm
     * @param y2         second end's y, mm
     * @param numPoints  how many scan points it covers
     * @param startPoint the first point's number
     * @param endPoint   the last point's number
     */
    public final void newEndPoints(double x1, double y1, double x2, double y2, int numPoints, int startPoint,
            int endPoint) {
        this.x1 = x1;
        this.y1 = y1;
        this.x2 = x2;
        this.y2 = y2;
        lineAngle = Math.toDegrees(Math.atan2(y2 - y1, x2 - x1));
        length = Math.hypot(x2 - x1, y2 - y1);
        this.numPoints = numPoints;
        this.startPoint = startPoint;
        this.endPoint = endPoint;
        aveDistFromLine = 0;
    }

    /** @return first end's x */
    public double getX1() {
        return x1;
    }

    /** @return first end's y */
    public double getY1() {
        return y1;
    }

    /** @return second end's x */
    public double getX2() {
        return x2;
    }

    /** @return second end's y */
    public double getY2() {
        return y2;
    }

    /** @return the first end */
    public ArPose getEndPoint1() {
        return new ArPose(x1, y1, 0);
    }

    /** @return the second end */
    public ArPose getEndPoint2() {
        return new ArPose(x2, y2, 0);
    }

    /** @return its direction, first end to second, degrees */
    public double getLineAngle() {
        return lineAngle;
    }

    /** @return its length, mm */
    public double getLength() {
        return length;
    }

    /** @return how many scan points it covers */
    public int getNumPoints() {
        return numPoints;
    }

    /** @return the first point's number */
    public int getStartPoint() {
        return startPoint;
    }

    /** @return the last point's number */
    public int getEndPoint() {
        return endPoint;
    }

    /** @param ave the points' average distance from the line, mm */
    public void setAveDistFromLine(double ave) {
        aveDistFromLine = ave;
    }

    /** @return the points' average distance from the line, mm */
    public double getAveDistFromLine() {
        return aveDistFromLine;
    }

    // ---- ARIA's ArLine: a x + b y = c through the two ends ----

    double a() {
        return y1 - y2;
    }

    double b() {
        return x2 - x1;
    }

    double c() {
        return x2 * y1 - y2 * x1;
    }

    /**
     * Where two infinite lines a x + b y = c cross, as ARIA 2.x's {@code ArLine::intersects}.
     * (AriaCoda's has {@code line.getA()} for {@code line.getB()} in x, a slip of its refactoring
     * that puts the crossing off the lines; RoboSim keeps ARIA 2.x's.)
     *
     * @return the point, or null if they are parallel
     */
    static ArPose intersection(double a1, double b1, double c1, double a2, double b2, double c2) {
        return ArLineSegment.crossing(a1, b1, c1, a2, b2, c2);
    }

    /** @return where this segment's line crosses the other's, or null if parallel */
    ArPose lineIntersection(ArLineFinderSegment other) {
        return intersection(a(), b(), c(), other.a(), other.b(), other.c());
    }

    /** @return the foot of the perpendicular from a point to this segment's line, or null */
    ArPose perpPoint(ArPose pose) {
        // ARIA's makeLinePerp: (-b, a, a y - b x)
        return intersection(a(), b(), c(), -b(), a(), a() * pose.getY() - b() * pose.getX());
    }

    /**
     * @param pose a point
     * @return its distance from this segment's (infinite) line, as AriaCoda's
     *         {@code ArLineSegment::getDistToLine}; for a segment of no length, from the nearer end
     */
    public double getDistToLine(ArPose pose) {
        ArPose perp = perpPoint(pose);
        if (perp == null) {
            return Math.min(ArMath.roundInt(getEndPoint1().findDistanceTo(pose)),
                    ArMath.roundInt(getEndPoint2().findDistanceTo(pose)));
        }
        return perp.findDistanceTo(pose);
    }

    @Override
    public String toString() {
        return String.format("(%.0f, %.0f)-(%.0f, %.0f) %d points [%d-%d]", x1, y1, x2, y2, numPoints, startPoint,
                endPoint);
    }
}
