package robosim.aria;

/**
 * A line found in a laser scan, as ARIA's {@code ArLineFinderSegment} (ArLineFinder.h): an
 * {@link ArLineSegment}, with its angle and length, how many scan points it covers (first and last
 * by number) and their average distance from it. {@link #getDistToLine} is ARIA's (AriaCoda's): the
 * distance from the infinite line through the end points.
 */
public class ArLineFinderSegment extends ArLineSegment {
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
        newEndPoints(other.getX1(), other.getY1(), other.getX2(), other.getY2(), other.numPoints, other.startPoint,
                other.endPoint);
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
        newEndPoints(x1, y1, x2, y2);
        this.numPoints = numPoints;
        this.startPoint = startPoint;
        this.endPoint = endPoint;
        aveDistFromLine = 0;
    }

    /** Moves the ends, keeping the points covered; the angle and length follow. */
    @Override
    public void newEndPoints(double x1, double y1, double x2, double y2) {
        super.newEndPoints(x1, y1, x2, y2);
        lineAngle = Math.toDegrees(Math.atan2(y2 - y1, x2 - x1));
        length = Math.hypot(x2 - x1, y2 - y1);
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

    /** @return where this segment's line crosses the other's, or null if parallel */
    ArPose lineIntersection(ArLineFinderSegment other) {
        return crossing(getA(), getB(), getC(), other.getA(), other.getB(), other.getC());
    }

    /** @return the foot of the perpendicular from a point to this segment's line, or null */
    ArPose perpPoint(ArPose pose) {
        // ARIA's makeLinePerp: (-b, a, a y - b x)
        return crossing(getA(), getB(), getC(), -getB(), getA(), getA() * pose.getY() - getB() * pose.getX());
    }

    @Override
    public String toString() {
        return String.format("(%.0f, %.0f)-(%.0f, %.0f) %d points [%d-%d]", getX1(), getY1(), getX2(), getY2(),
                numPoints, startPoint, endPoint);
    }
}
