package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.algorithm.ConvexHull;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Polygon;

/** The motion queries' exact ring tests give JTS's answers: touching counts, containment counts. */
class RingsTest {
    private static final GeometryFactory FACTORY = new GeometryFactory();

    private static Coordinate[] ring(double... xy) {
        return GeometryClient.polygon(xy).getExteriorRing().getCoordinates();
    }

    private static Coordinate[] square(double x0, double y0, double side) {
        return ring(x0, y0, x0 + side, y0, x0 + side, y0 + side, x0, y0 + side);
    }

    @Test
    void overlappingSquaresIntersect() {
        assertTrue(Rings.intersect(square(0, 0, 10), square(5, 5, 10)));
    }

    @Test
    void squaresSharingAnEdgeOrACornerIntersect() {
        assertTrue(Rings.intersect(square(0, 0, 10), square(10, 0, 10)), "edge");
        assertTrue(Rings.intersect(square(0, 0, 10), square(10, 10, 10)), "corner");
        assertTrue(Rings.intersect(square(0, 0, 10), square(10, 3, 4)), "part of an edge, collinear");
    }

    @Test
    void aRingWhollyInsideTheOtherIntersectsItEitherWayRound() {
        assertTrue(Rings.intersect(square(0, 0, 10), square(2, 2, 3)));
        assertTrue(Rings.intersect(square(2, 2, 3), square(0, 0, 10)));
    }

    @Test
    void ringsApartDoNotIntersectEvenWhenTheirEnvelopesOverlap() {
        assertFalse(Rings.intersect(square(0, 0, 10), square(10.001, 0, 10)));
        // two triangles on either side of the diagonal x + y = 10
        assertFalse(Rings.intersect(ring(0, 0, 9.99, 0, 0, 9.99), ring(10, 10, 0.01, 10, 10, 0.01)));
    }

    @Test
    void bodiesInAndNearContactGiveWhatPolygonIntersectsGives() {
        Random random = new Random(42);
        BodyShape[] shapes = {Worlds.P3DX, BodyShape.disc(250, 16), BodyShape.regularPolygon(180, 7)};
        int touching = 0;
        for (int i = 0; i < 5000; i++) {
            BodyShape a = shapes[random.nextInt(shapes.length)];
            BodyShape b = shapes[random.nextInt(shapes.length)];
            Pose2D pa = new Pose2D(random.nextDouble() * 100, random.nextDouble() * 100, random.nextDouble() * 7);
            double d = a.radius() + b.radius() * random.nextDouble() * 1.2;
            double dir = random.nextDouble() * 2 * Math.PI;
            Pose2D pb = new Pose2D(pa.x() + d * Math.cos(dir), pa.y() + d * Math.sin(dir), random.nextDouble() * 7);
            Coordinate[] ra = a.ringAt(pa);
            Coordinate[] rb = b.ringAt(pb);
            boolean jts = FACTORY.createPolygon(ra).intersects(FACTORY.createPolygon(rb));
            assertEquals(jts, Rings.intersect(ra, rb), "at " + pa + " and " + pb);
            touching += jts ? 1 : 0;
        }
        assertTrue(touching > 500 && touching < 4500, "both answers were tested: " + touching + " touching");
    }

    @Test
    void theHullOfABodyAtTwoPosesEnclosesWhatJtsConvexHullEncloses() {
        Random random = new Random(7);
        for (BodyShape shape : new BodyShape[] {Worlds.P3DX, BodyShape.disc(250, 16)}) {
            for (int i = 0; i < 1000; i++) {
                Pose2D a = new Pose2D(random.nextDouble() * 1000, random.nextDouble() * 1000, random.nextDouble() * 7);
                Pose2D b = i % 3 == 0 ? a : a.advance(random.nextDouble() * 60 - 30, random.nextDouble() * 0.1 - 0.05);
                Coordinate[] ra = shape.ringAt(a);
                Coordinate[] rb = shape.ringAt(b);
                Coordinate[] all = new Coordinate[ra.length + rb.length];
                System.arraycopy(ra, 0, all, 0, ra.length);
                System.arraycopy(rb, 0, all, ra.length, rb.length);
                Geometry jts = new ConvexHull(all, FACTORY).getConvexHull();
                Polygon ours = FACTORY.createPolygon(Rings.hull(ra, rb));
                assertTrue(ours.isValid(), "a valid ring: " + ours);
                assertTrue(ours.equalsTopo(jts), "the same area: " + ours + " and " + jts);
            }
        }
    }

    @Test
    void theHullIsClosedAndCounterClockwise() {
        Coordinate[] h = Rings.hull(square(0, 0, 10), square(5, 5, 10));
        assertEquals(h[0], h[h.length - 1]);
        assertEquals(7, h.length, "six corners, the two inner ones left out");
        assertTrue(org.locationtech.jts.algorithm.Orientation.isCCW(h));
    }
}
