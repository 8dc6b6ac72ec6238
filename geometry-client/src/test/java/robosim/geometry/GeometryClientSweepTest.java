package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.geometry.Worlds.P3DX;
import static robosim.geometry.Worlds.box;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Polygon;

/**
 * Swept motion: a body stops at contact, within 0.1 mm of what it hit and never overlapping it, and
 * a free motion ends exactly where {@link Pose2D#advance} says.
 */
class GeometryClientSweepTest {
    private static final double CONTACT = 0.1;
    private static final GeometryFactory FACTORY = new GeometryFactory();

    private static Polygon bodyAt(Pose2D pose) {
        return FACTORY.createPolygon(P3DX.ringAt(pose));
    }

    /** The body at the swept pose is nearer than 0.1 mm to the obstacle, and does not touch it. */
    private static void assertInContact(GeometryClient world, int id, SweepResult result, Geometry obstacle) {
        assertTrue(result.blocked(), "blocked");
        assertFalse(world.overlaps(P3DX, result.pose(), id), "overlaps at " + result.pose());
        double gap = bodyAt(result.pose()).distance(obstacle);
        assertTrue(gap > 0 && gap < CONTACT, "gap " + gap + " mm at " + result.pose());
    }

    @Test
    void drivingStraightIntoAWallStopsAtContact() {
        Polygon wall = box(1000, -2000, 1100, 2000);
        GeometryClient world = new GeometryClient(List.of(wall));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        SweepResult r = world.sweep(id, 2000, 0);

        assertInContact(world, id, r, wall);
    }

    @Test
    void drivingStraightIntoAWallStopsWithTheFrontAtTheWall() {
        GeometryClient world = new GeometryClient(List.of(box(1000, -2000, 1100, 2000)));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        SweepResult r = world.sweep(id, 2000, 0);

        // the front face is 210 mm ahead of the centre: contact at x = 790, 790 of 2000 mm travelled
        assertEquals(790, r.pose().x(), 0.05);
        assertTrue(r.pose().x() < 790);
        assertEquals(0, r.pose().y());
        assertEquals(0, r.pose().th());
        assertEquals(790.0 / 2000, r.fraction(), 0.05 / 2000);
    }

    @Test
    void backingIntoAWallStopsWithTheRearAtTheWall() {
        Polygon wall = box(-1100, -2000, -1000, 2000);
        GeometryClient world = new GeometryClient(List.of(wall));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        SweepResult r = world.sweep(id, -2000, 0);

        // the rear face is 301 mm behind the centre
        assertEquals(-699, r.pose().x(), 0.05);
        assertInContact(world, id, r, wall);
    }

    @Test
    void drivingDiagonallyIntoACornerStopsAtContactNotInside() {
        Polygon east = box(1000, -2000, 1100, 1100);
        Polygon north = box(-2000, 1000, 1000, 1100);
        GeometryClient world = new GeometryClient(List.of(east, north));
        int id = world.addBody(P3DX, new Pose2D(0, 0, Math.PI / 4));

        SweepResult r = world.sweep(id, 3000, 0);

        // at 45° the front corners reach (210 + 212.5) / √2 = 298.75 mm beyond the centre in x and in y,
        // so both walls are met together with the centre at 1000 - 298.75 = 701.25 on each axis
        double c = 1000 - 422.5 / Math.sqrt(2);
        assertEquals(c, r.pose().x(), 0.05);
        assertEquals(c, r.pose().y(), 0.05);
        assertInContact(world, id, r, east);
        assertInContact(world, id, r, north);
    }

    @Test
    void fastRobotDoesNotTunnelThroughAThinWall() {
        Polygon wall = box(1000, -2000, 1010, 2000);
        GeometryClient world = new GeometryClient(List.of(wall));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        SweepResult r = world.sweep(id, 5000, 0);

        assertEquals(790, r.pose().x(), 0.05);
        assertInContact(world, id, r, wall);
    }

    @Test
    void fastRobotDoesNotTunnelThroughAnotherBody() {
        GeometryClient world = new GeometryClient(List.of());
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));
        world.addBody(BodyShape.rectangle(5, 5, 400), new Pose2D(2000, 0, 0));

        SweepResult r = world.sweep(id, 5000, 0);

        // the other body's rear face is at 1995
        assertTrue(r.blocked());
        assertEquals(1995 - 210, r.pose().x(), 0.05);
    }

    @Test
    void turningInPlaceIntoAWallIsBlockedByTheCorner() {
        // the front-right corner (210, -212.5), 298.75 mm from the centre, swings out to x = 260 when
        // the heading reaches atan2(212.5, 210) - acos(260 / 298.75) = 45.34° - 29.51° = 15.83°
        Polygon wall = box(260, -1000, 400, 1000);
        GeometryClient world = new GeometryClient(List.of(wall));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        SweepResult r = world.sweep(id, 0, Math.PI / 2);

        double contact = Math.atan2(212.5, 210) - Math.acos(260 / Math.hypot(210, 212.5));
        assertEquals(15.83, Math.toDegrees(contact), 0.01);
        assertEquals(contact, r.pose().th(), 2e-4);
        assertEquals(0, r.pose().x(), 1e-9);
        assertEquals(0, r.pose().y(), 1e-9);
        assertInContact(world, id, r, wall);
    }

    @Test
    void turningInPlaceWithCornersClearOfTheWallIsFree() {
        // the front corners swing out to 298.75 mm; a wall at 300 mm is just out of reach
        GeometryClient world = new GeometryClient(List.of(box(300, -1000, 400, 1000)));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        SweepResult r = world.sweep(id, 0, Math.PI / 2);

        assertFalse(r.blocked());
        assertEquals(1.0, r.fraction());
        assertEquals(new Pose2D(0, 0, Math.PI / 2), r.pose());
    }

    @Test
    void freeQuarterCircleEndsAtTheExactArcEnd() {
        GeometryClient world = new GeometryClient(List.of(Worlds.room()));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        SweepResult r = world.sweep(id, Math.PI / 2 * 1000, Math.PI / 2);

        assertFalse(r.blocked());
        assertEquals(1.0, r.fraction());
        assertEquals(1000, r.pose().x(), 1e-9);
        assertEquals(1000, r.pose().y(), 1e-9);
        assertEquals(Math.PI / 2, r.pose().th(), 1e-12);
    }

    @Test
    void freeStraightMotionEndsAtTheExactEnd() {
        GeometryClient world = new GeometryClient(List.of());
        int id = world.addBody(P3DX, new Pose2D(100, 200, 0));

        SweepResult r = world.sweep(id, 1500, 0);

        assertEquals(new SweepResult(1, new Pose2D(1600, 200, 0), false), r);
    }

    @Test
    void drivingAlongsideAWallIsFree() {
        // the body's side is at y = 212.5, the wall's face at y = 213
        GeometryClient world = new GeometryClient(List.of(box(-2000, 213, 4000, 300)));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        SweepResult r = world.sweep(id, 3000, 0);

        assertFalse(r.blocked());
        assertEquals(new Pose2D(3000, 0, 0), r.pose());
    }

    @Test
    void arcIntoAWallStopsOnTheArcAtContact() {
        Polygon wall = box(-3000, 1100, 3000, 1200);
        GeometryClient world = new GeometryClient(List.of(wall));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        SweepResult r = world.sweep(id, Math.PI / 2 * 1000, Math.PI / 2);

        // still on the circle of radius 1000 about (0, 1000), facing along it
        Pose2D p = r.pose();
        assertEquals(1000, Math.hypot(p.x(), p.y() - 1000), 1e-6);
        assertEquals(Math.atan2(p.x(), 1000 - p.y()), p.th(), 1e-9);
        assertEquals(r.fraction() * Math.PI / 2, p.th(), 1e-9);
        assertInContact(world, id, r, wall);
    }

    @Test
    void bodyDrivingIntoAnotherBodyStopsAtContact() {
        GeometryClient world = new GeometryClient(List.of());
        int mover = world.addBody(P3DX, new Pose2D(0, 0, 0));
        int other = world.addBody(P3DX, new Pose2D(2000, 0, 0));

        SweepResult r = world.sweep(mover, 3000, 0);

        // the mover's front (x + 210) meets the other's rear (2000 - 301)
        assertEquals(1489, r.pose().x(), 0.05);
        assertInContact(world, mover, r, world.bodyPolygon(other));
    }

    @Test
    void bodyIsNotBlockedByItself() {
        GeometryClient world = new GeometryClient(List.of());
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        SweepResult r = world.sweep(id, 100, 0.5);

        assertFalse(r.blocked());
    }

    @Test
    void sweepDoesNotMoveTheBody() {
        GeometryClient world = new GeometryClient(List.of(box(1000, -2000, 1100, 2000)));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        world.sweep(id, 2000, 0);

        assertEquals(new Pose2D(0, 0, 0), world.bodyPose(id));
    }

    @Test
    void bodyAlreadyTouchingAWallCannotMoveTowardsIt() {
        GeometryClient world = new GeometryClient(List.of(box(1000, -2000, 1100, 2000)));
        int id = world.addBody(P3DX, new Pose2D(790, 0, 0));

        SweepResult r = world.sweep(id, 100, 0);

        assertTrue(r.blocked());
        assertEquals(0, r.fraction());
        assertEquals(new Pose2D(790, 0, 0), r.pose());
    }

    @Test
    void bodyInContactCanBackAway() {
        GeometryClient world = new GeometryClient(List.of(box(1000, -2000, 1100, 2000)));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));
        world.moveBody(id, world.sweep(id, 2000, 0).pose());

        SweepResult r = world.sweep(id, -500, 0);

        assertFalse(r.blocked());
    }

    @Test
    void anAbsurdSpinIsSweptAsOneTurnAndEndsWhereTheArcSays() {
        // 10^12 radians would once have been cut into 2^31 pieces; the poses repeat every turn
        GeometryClient world = new GeometryClient(List.of(box(600, -1000, 700, 1000)));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        SweepResult r = world.sweep(id, 0, 1e12);

        assertFalse(r.blocked());
        assertEquals(new Pose2D(0, 0, 0).advance(0, 1e12), r.pose());
    }

    @Test
    void anAbsurdSpinIntoAWallStopsAtTheSameContactAsAQuarterTurn() {
        Polygon wall = box(260, -1000, 400, 1000);
        GeometryClient world = new GeometryClient(List.of(wall));
        int id = world.addBody(P3DX, new Pose2D(0, 0, 0));

        SweepResult spin = world.sweep(id, 0, 1e12);
        SweepResult quarter = world.sweep(id, 0, Math.PI / 2);

        assertEquals(quarter.pose().th(), spin.pose().th(), 2e-4);
        assertInContact(world, id, spin, wall);
    }

    @Test
    void theWorkOfASweepIsBoundedWhateverIsAsked() {
        assertEquals(1, GeometryClient.pieces(1e300, 0));
        assertEquals(120, GeometryClient.pieces(0, 2 * Math.PI));
        assertEquals(GeometryClient.MAX_PIECES, GeometryClient.pieces(1e300, 2 * Math.PI));
        assertEquals(1, GeometryClient.pieces(Double.NaN, Double.NaN));
    }
}
