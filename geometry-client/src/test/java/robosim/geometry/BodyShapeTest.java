package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.locationtech.jts.algorithm.Orientation;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.GeometryFactory;

class BodyShapeTest {
    private static final BodyShape P3DX = BodyShape.rectangle(210, 301, 425);

    @Test
    void rectangleRingAtTheOrigin() {
        Coordinate[] ring = P3DX.ringAt(new Pose2D(0, 0, 0));

        assertEquals(5, ring.length);
        assertEquals(new Coordinate(210, 212.5), ring[0]);
        assertEquals(new Coordinate(-301, 212.5), ring[1]);
        assertEquals(new Coordinate(-301, -212.5), ring[2]);
        assertEquals(new Coordinate(210, -212.5), ring[3]);
        assertEquals(ring[0], ring[4]);
    }

    @Test
    void ringIsCounterClockwise() {
        assertTrue(Orientation.isCCW(P3DX.ringAt(new Pose2D(10, 20, 2.0))));
    }

    @Test
    void rectangleRingFollowsThePose() {
        Coordinate[] ring = P3DX.ringAt(new Pose2D(1000, 2000, Math.PI / 2));

        // front-left (210, 212.5) of a robot heading +y lies at (1000 - 212.5, 2000 + 210)
        assertEquals(787.5, ring[0].x, 1e-9);
        assertEquals(2210, ring[0].y, 1e-9);
    }

    @Test
    void rectangleAreaIsLengthTimesWidth() {
        double area = new GeometryFactory().createPolygon(P3DX.ringAt(new Pose2D(5, 5, 0.7))).getArea();

        assertEquals(511 * 425, area, 1e-6);
    }

    @Test
    void rectangleRadiusReachesTheRearCorners() {
        assertEquals(Math.hypot(301, 212.5), P3DX.radius(), 1e-12);
        assertEquals(4, P3DX.size());
    }

    @Test
    void regularPolygonHasItsVerticesOnTheCircle() {
        BodyShape hexagon = BodyShape.regularPolygon(250, 6);

        Coordinate[] ring = hexagon.ringAt(new Pose2D(0, 0, 0));

        assertEquals(6, hexagon.size());
        assertEquals(250, hexagon.radius(), 1e-12);
        assertEquals(250, ring[0].x, 1e-12);
        assertEquals(0, ring[0].y, 1e-12);
        assertEquals(125, ring[1].x, 1e-9);
        assertEquals(125 * Math.sqrt(3), ring[1].y, 1e-9);
    }

    @ParameterizedTest
    @CsvSource({
        "0, 301, 425, '0.0 was supplied for front: front must be greater than 0'",
        "210, -301, 425, '-301.0 was supplied for rear: rear must be greater than 0'",
        "210, 301, 0, '0.0 was supplied for width: width must be greater than 0'",
        "NaN, 301, 425, 'NaN was supplied for front: front must be greater than 0'",
        "210, Infinity, 425, 'Infinity was supplied for rear: rear must be greater than 0'",
    })
    void rectangleRejectsABadSize(double front, double rear, double width, String message) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> BodyShape.rectangle(front, rear, width));

        assertEquals(message, e.getMessage());
    }

    @ParameterizedTest
    @ValueSource(doubles = {0, -250, Double.NaN})
    void regularPolygonRejectsABadRadius(double radius) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> BodyShape.regularPolygon(radius, 8));

        assertEquals(radius + " was supplied for radius: radius must be greater than 0", e.getMessage());
    }

    @ParameterizedTest
    @ValueSource(ints = {2, 0, -3})
    void regularPolygonRejectsTooFewSides(int sides) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> BodyShape.regularPolygon(250, sides));

        assertEquals(sides + " was supplied for sides: sides must be at least 3", e.getMessage());
    }
}
