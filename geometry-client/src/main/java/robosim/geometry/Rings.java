package robosim.geometry;

import java.util.Arrays;
import org.locationtech.jts.algorithm.Orientation;
import org.locationtech.jts.algorithm.RayCrossingCounter;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Location;

/**
 * Exact tests on small closed rings (first point repeated last), for the motion queries, which ask
 * them several times a step for every robot in contact. They decide with JTS's exact orientation
 * predicate ({@link Orientation#index}) and its ray-crossing point location, as JTS's own predicates
 * do, so they give the answers JTS gives, without building JTS's topology graphs (for two polygons
 * whose envelopes meet, tens of microseconds and kilobytes of garbage per test).
 */
final class Rings {
    private Rings() {
    }

    /**
     * Whether the areas two simple rings enclose share a point, their boundaries included: what
     * {@code Polygon.intersects} answers for two polygons without holes. Either some edge of one
     * meets an edge of the other, or, if none does, one lies wholly inside the other, which one
     * vertex of each tells.
     *
     * @param a a closed ring, simple
     * @param b a closed ring, simple
     * @return true if they touch or overlap
     */
    static boolean intersect(Coordinate[] a, Coordinate[] b) {
        Envelope eb = envelope(b);
        if (!envelope(a).intersects(eb)) {
            return false;
        }
        for (int i = 0; i + 1 < a.length; i++) {
            Coordinate p1 = a[i];
            Coordinate p2 = a[i + 1];
            if (!eb.intersects(p1, p2)) {
                continue;
            }
            for (int j = 0; j + 1 < b.length; j++) {
                if (segmentsMeet(p1, p2, b[j], b[j + 1])) {
                    return true;
                }
            }
        }
        return RayCrossingCounter.locatePointInRing(a[0], b) != Location.EXTERIOR
                || RayCrossingCounter.locatePointInRing(b[0], a) != Location.EXTERIOR;
    }

    /**
     * Whether two closed segments share a point, decided as JTS's {@code RobustLineIntersector}
     * decides it: by their envelopes, then by the exact orientation of each segment's ends to the
     * other (collinear segments whose envelopes meet overlap).
     */
    static boolean segmentsMeet(Coordinate p1, Coordinate p2, Coordinate q1, Coordinate q2) {
        if (!Envelope.intersects(p1, p2, q1, q2)) {
            return false;
        }
        int pq1 = Orientation.index(p1, p2, q1);
        int pq2 = Orientation.index(p1, p2, q2);
        if (pq1 > 0 && pq2 > 0 || pq1 < 0 && pq2 < 0) {
            return false;
        }
        int qp1 = Orientation.index(q1, q2, p1);
        int qp2 = Orientation.index(q1, q2, p2);
        return !(qp1 > 0 && qp2 > 0 || qp1 < 0 && qp2 < 0);
    }

    /**
     * The convex hull of the vertices of two closed rings (Andrew's monotone chain, turning by the
     * exact orientation predicate, so it encloses exactly what JTS's {@code ConvexHull} of the same
     * points encloses).
     *
     * @param a a closed ring
     * @param b a closed ring; the two together have three points not in a line, as a body's do
     * @return the hull as a closed counter-clockwise ring of input points, no three in a line
     */
    static Coordinate[] hull(Coordinate[] a, Coordinate[] b) {
        Coordinate[] pts = new Coordinate[a.length - 1 + b.length - 1];
        System.arraycopy(a, 0, pts, 0, a.length - 1);
        System.arraycopy(b, 0, pts, a.length - 1, b.length - 1);
        sortByXThenY(pts);
        Coordinate[] h = new Coordinate[2 * pts.length + 1];
        int k = 0;
        for (Coordinate p : pts) {
            while (k >= 2 && Orientation.index(h[k - 2], h[k - 1], p) != Orientation.COUNTERCLOCKWISE) {
                k--;
            }
            h[k++] = p;
        }
        for (int i = pts.length - 2, lower = k + 1; i >= 0; i--) {
            Coordinate p = pts[i];
            while (k >= lower && Orientation.index(h[k - 2], h[k - 1], p) != Orientation.COUNTERCLOCKWISE) {
                k--;
            }
            h[k++] = p;
        }
        // the lower chain started at the leftmost point and the upper chain ends there: closed
        return Arrays.copyOf(h, k);
    }

    /**
     * Sorts a few points by x, then y, as {@code Double.compare} orders them (-0.0 before 0.0),
     * keeping equal points in their order: the order {@code Arrays.sort} gives with that comparator,
     * by insertion, which for the 8 to 64 points of two bodies' rings is quicker than a merge sort
     * calling a composed comparator.
     */
    private static void sortByXThenY(Coordinate[] pts) {
        for (int i = 1; i < pts.length; i++) {
            Coordinate p = pts[i];
            int j = i - 1;
            while (j >= 0 && after(pts[j], p)) {
                pts[j + 1] = pts[j];
                j--;
            }
            pts[j + 1] = p;
        }
    }

    /** Whether {@code a} comes strictly after {@code b} by x, then y. */
    private static boolean after(Coordinate a, Coordinate b) {
        int byX = Double.compare(a.x, b.x);
        return byX > 0 || byX == 0 && Double.compare(a.y, b.y) > 0;
    }

    private static Envelope envelope(Coordinate[] ring) {
        Envelope e = new Envelope();
        for (Coordinate c : ring) {
            e.expandToInclude(c);
        }
        return e;
    }
}
