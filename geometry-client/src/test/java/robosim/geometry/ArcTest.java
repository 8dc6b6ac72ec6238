package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.locationtech.jts.geom.Coordinate;

class ArcTest {
    private static final BodyShape P3DX = BodyShape.rectangle(210, 301, 425);

    /** A place is the pose Pose2D.advance gives and the ring BodyShape.ringAt gives there, bit for bit. */
    @ParameterizedTest
    @CsvSource({
        "1000.3, -2000.7, 0.3, 31.7, 0",
        "1000.3, -2000.7, 0.3, -31.7, 0",
        "1000.3, -2000.7, 2.9, 31.7, 0.0523",
        "-5.5, 7.25, -1.2, 0, -0.0523",
        "0, 0, 3.14159, 412.9, 1e-13",
        "12345.6, 789.1, -3.1, -50, 6.5",
    })
    void placesAreWhereAdvanceAndRingAtPutThem(double x, double y, double th, double distance, double rotation) {
        Pose2D start = new Pose2D(x, y, th);
        Arc arc = new Arc(P3DX, start, distance, rotation);
        for (double f : new double[] {0, 1e-7, 0.125, 1.0 / 3, 0.5, 0.999, 1}) {
            Pose2D expected = start.advance(distance * f, rotation * f);
            Arc.Place place = arc.at(f);

            assertEquals(expected, place.pose());
            Coordinate[] ring = P3DX.ringAt(expected);
            for (int i = 0; i < ring.length; i++) {
                assertEquals(Double.doubleToRawLongBits(ring[i].x), Double.doubleToRawLongBits(place.ring()[i].x));
                assertEquals(Double.doubleToRawLongBits(ring[i].y), Double.doubleToRawLongBits(place.ring()[i].y));
            }
        }
    }
}
