package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.geometry.Worlds.P3DX;
import static robosim.geometry.Worlds.box;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Polygon;

/** Building the world: polygons, bodies and the overlap test. */
class GeometryClientTest {

    @Test
    void polygonFromFlatCoordinatesIsClosed() {
        Polygon p = GeometryClient.polygon(0, 0, 400, 0, 400, 100, 0, 100);

        assertEquals(5, p.getNumPoints());
        assertEquals(40000, p.getArea());
    }

    @Test
    void polygonNeedsThreePoints() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> GeometryClient.polygon(0, 0, 1, 1));

        assertEquals("a polygon needs at least 3 points as x,y pairs, got 4 numbers", e.getMessage());
    }

    @Test
    void polygonNeedsPairs() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> GeometryClient.polygon(0, 0, 1, 0, 1, 1, 0));

        assertEquals("a polygon needs at least 3 points as x,y pairs, got 7 numbers", e.getMessage());
    }

    @Test
    void bodiesAreNumberedInOrder() {
        GeometryClient world = new GeometryClient(List.of());

        assertEquals(0, world.addBody(P3DX, new Pose2D(0, 0, 0)));
        assertEquals(1, world.addBody(P3DX, new Pose2D(1000, 0, 0)));
    }

    @Test
    void movedBodyHasItsNewPoseAndOutline() {
        GeometryClient world = new GeometryClient(List.of());
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        world.moveBody(id, new Pose2D(1000, 500, 0));

        assertEquals(new Pose2D(1000, 500, 0), world.bodyPose(id));
        assertEquals(box(1000 - 301, 500 - 212.5, 1000 + 210, 500 + 212.5).getEnvelopeInternal(),
                world.bodyPolygon(id).getEnvelopeInternal());
    }

    @Test
    void bodyClearOfTheWallDoesNotOverlap() {
        GeometryClient world = new GeometryClient(List.of(box(1000, -2000, 1100, 2000)));

        assertFalse(world.overlaps(P3DX, new Pose2D(789.9, 0, 0), -1));
    }

    @Test
    void bodyTouchingTheWallOverlaps() {
        GeometryClient world = new GeometryClient(List.of(box(1000, -2000, 1100, 2000)));

        assertTrue(world.overlaps(P3DX, new Pose2D(790, 0, 0), -1));
    }

    @Test
    void bodyInsideARoomDoesNotOverlapItsWalls() {
        GeometryClient world = new GeometryClient(List.of(Worlds.room()));

        assertFalse(world.overlaps(P3DX, new Pose2D(0, 0, 1.0), -1));
    }

    @Test
    void bodyOverlapsAnotherBody() {
        GeometryClient world = new GeometryClient(List.of());
        world.addBody(P3DX, new Pose2D(0, 0, 0));

        assertTrue(world.overlaps(P3DX, new Pose2D(400, 0, 0), -1));
    }

    @Test
    void bodyDoesNotOverlapTheIgnoredBody() {
        GeometryClient world = new GeometryClient(List.of());
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        assertFalse(world.overlaps(P3DX, new Pose2D(100, 0, 0), id));
    }
}
