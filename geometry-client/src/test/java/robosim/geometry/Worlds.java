package robosim.geometry;

import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.LinearRing;
import org.locationtech.jts.geom.Polygon;

/** Literal shapes shared by the GeometryClient tests. */
final class Worlds {
    /** The Pioneer 3 DX body: 210 mm ahead of the centre, 301 behind, 425 across. */
    static final BodyShape P3DX = BodyShape.rectangle(210, 301, 425);

    private Worlds() {
    }

    static Polygon box(double minX, double minY, double maxX, double maxY) {
        return GeometryClient.polygon(minX, minY, maxX, minY, maxX, maxY, minX, maxY);
    }

    /** A 4000 × 4000 mm room about the origin with 100 mm walls: one polygon with a hole. */
    static Polygon room() {
        GeometryFactory f = new GeometryFactory();
        LinearRing outer = f.createLinearRing(box(-2100, -2100, 2100, 2100).getExteriorRing().getCoordinates());
        LinearRing inner = f.createLinearRing(box(-2000, -2000, 2000, 2000).getExteriorRing().getCoordinates());
        return f.createPolygon(outer, new LinearRing[] {inner});
    }
}
