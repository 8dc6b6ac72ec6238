package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static robosim.geometry.Worlds.P3DX;
import static robosim.geometry.Worlds.box;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.locationtech.jts.geom.Polygon;

/** Ray and sonar-cone ranges in literal worlds, against values worked out by hand. */
class GeometryClientRangeTest {
    private static final double EPS = 1e-6;
    private static final double HALF_CONE = Math.toRadians(15);
    private static final double MAX_RANGE = 5000;

    private static GeometryClient world(Polygon... obstacles) {
        return new GeometryClient(List.of(obstacles));
    }

    // --- rays ---

    @ParameterizedTest(name = "{0}°")
    @ValueSource(doubles = {0, 30, -30, 60, -60})
    void rayToAWallAlongXIsTheWallDistanceOverTheCosine(double degrees) {
        GeometryClient world = world(box(1000, -5000, 1100, 5000));

        double range = world.rayRange(0, 0, Math.toRadians(degrees), MAX_RANGE, -1);

        assertEquals(1000 / Math.cos(Math.toRadians(degrees)), range, EPS);
    }

    @Test
    void rayAtThirtyDegreesToAWallAtOneMetre() {
        GeometryClient world = world(box(1000, -5000, 1100, 5000));

        // 1000 / cos 30° = 2000 / √3
        assertEquals(1154.700538, world.rayRange(0, 0, Math.toRadians(30), MAX_RANGE, -1), EPS);
    }

    @Test
    void rayFromAnOffsetOriginAtFortyFiveDegrees() {
        GeometryClient world = world(box(-5000, 3000, 5000, 3100));

        // from (500, 1000) up to y = 3000: 2000 · √2
        assertEquals(2000 * Math.sqrt(2), world.rayRange(500, 1000, Math.toRadians(45), MAX_RANGE, -1), EPS);
    }

    @Test
    void rayPassingBesideAShortWallGivesMaxRange() {
        // the 30° ray crosses x = 1000 at y = 577, above the wall's end at y = 100
        GeometryClient world = world(box(1000, -100, 1010, 100));

        assertEquals(MAX_RANGE, world.rayRange(0, 0, Math.toRadians(30), MAX_RANGE, -1));
    }

    @Test
    void rayPointingAwayFromTheWallGivesMaxRange() {
        GeometryClient world = world(box(1000, -5000, 1100, 5000));

        assertEquals(MAX_RANGE, world.rayRange(0, 0, Math.PI, MAX_RANGE, -1));
    }

    @Test
    void wallBeyondMaxRangeGivesMaxRange() {
        GeometryClient world = world(box(1000, -5000, 1100, 5000));

        assertEquals(900, world.rayRange(0, 0, 0, 900, -1));
    }

    @Test
    void rayInAnEmptyWorldGivesMaxRange() {
        assertEquals(MAX_RANGE, world().rayRange(0, 0, 1.0, MAX_RANGE, -1));
    }

    @Test
    void rayMeetsTheNearestOfTwoWalls() {
        GeometryClient world = world(box(3000, -5000, 3100, 5000), box(1000, -5000, 1100, 5000));

        assertEquals(1000, world.rayRange(0, 0, 0, MAX_RANGE, -1), EPS);
    }

    @Test
    void rayInsideARoomMeetsTheInnerWall() {
        GeometryClient world = new GeometryClient(List.of(Worlds.room()));

        assertEquals(2000, world.rayRange(0, 0, Math.PI / 2, MAX_RANGE, -1), EPS);
    }

    @Test
    void raySeesAnotherBody() {
        GeometryClient world = world();
        int self = world.addBody(P3DX, new Pose2D(0, 0, 0));
        world.addBody(P3DX, new Pose2D(1500, 0, 0));

        // from the front face (x = 210) to the other's rear face (x = 1500 - 301)
        assertEquals(989, world.rayRange(210, 0, 0, MAX_RANGE, self), EPS);
    }

    @Test
    void rayDoesNotSeeTheIgnoredBody() {
        GeometryClient world = world();
        int self = world.addBody(P3DX, new Pose2D(0, 0, 0));

        assertEquals(MAX_RANGE, world.rayRange(0, 0, 0, MAX_RANGE, self));
    }

    @Test
    void rayFromInsideABodyItDoesNotIgnoreMeetsItsEdge() {
        GeometryClient world = world();
        world.addBody(P3DX, new Pose2D(0, 0, 0));

        assertEquals(210, world.rayRange(0, 0, 0, MAX_RANGE, -1), EPS);
    }

    @Test
    void rayFollowsAMovedBody() {
        GeometryClient world = world();
        int other = world.addBody(P3DX, new Pose2D(1500, 0, 0));

        world.moveBody(other, new Pose2D(2500, 0, 0));

        assertEquals(2500 - 301, world.rayRange(0, 0, 0, MAX_RANGE, -1), EPS);
    }

    // --- cones ---

    @ParameterizedTest(name = "axis {0}°")
    @CsvSource({
        "0, 2000, -3000, 2100, 3000",
        "90, -3000, 2000, 3000, 2100",
        "180, -2100, -3000, -2000, 3000",
        "-90, -3000, -2100, 3000, -2000",
    })
    void coneFacingAPerpendicularWallAtTwoMetres(double axis, double minX, double minY, double maxX, double maxY) {
        GeometryClient world = world(box(minX, minY, maxX, maxY));

        assertEquals(2000, world.coneRange(0, 0, Math.toRadians(axis), HALF_CONE, MAX_RANGE, -1), EPS);
    }

    @Test
    void coneSeesTheNearestPointOfAWallOnlyPartlyInside() {
        // the wall's face y = 600 enters the cone where the 15° edge crosses it, at x = 600 / tan 15°;
        // that point is the nearest inside: 600 / sin 15° = 2318.22 mm (the axis ray misses the wall)
        GeometryClient world = world(box(0, 600, 5000, 610));

        double range = world.coneRange(0, 0, 0, HALF_CONE, MAX_RANGE, -1);

        assertEquals(600 / Math.sin(HALF_CONE), range, EPS);
        assertEquals(2318.22, range, 0.01);
        assertEquals(MAX_RANGE, world.rayRange(0, 0, 0, MAX_RANGE, -1));
    }

    @Test
    void coneSeesACornerJustInsideTheEdge() {
        // the corner (2000, 530) lies at 14.8°; the face y = 530 is inside from x = 530 / tan 15° = 1978.0
        GeometryClient world = world(box(1000, 530, 2000, 800));

        assertEquals(530 / Math.sin(HALF_CONE), world.coneRange(0, 0, 0, HALF_CONE, MAX_RANGE, -1), EPS);
    }

    @Test
    void coneDoesNotSeeAnObstacleJustOutside() {
        // the nearest-to-axis corner (2000, 555) lies at 15.5°
        GeometryClient world = world(box(1000, 555, 2000, 800));

        assertEquals(MAX_RANGE, world.coneRange(0, 0, 0, HALF_CONE, MAX_RANGE, -1));
    }

    @Test
    void coneDoesNotSeeBehindItsApex() {
        GeometryClient world = world(box(-2100, -3000, -2000, 3000));

        assertEquals(MAX_RANGE, world.coneRange(0, 0, 0, HALF_CONE, MAX_RANGE, -1));
    }

    @Test
    void coneStopsAtMaxRange() {
        GeometryClient world = world(box(2000, -3000, 2100, 3000));

        assertEquals(1500, world.coneRange(0, 0, 0, HALF_CONE, 1500, -1));
    }

    @Test
    void coneSeesAnotherBody() {
        GeometryClient world = world();
        int self = world.addBody(P3DX, new Pose2D(0, 0, 0));
        world.addBody(P3DX, new Pose2D(1500, 0, 0));

        assertEquals(989, world.coneRange(210, 0, 0, HALF_CONE, MAX_RANGE, self), EPS);
    }

    @Test
    void coneDoesNotSeeItsOwnBody() {
        GeometryClient world = world(box(2000, -3000, 2100, 3000));
        int self = world.addBody(P3DX, new Pose2D(0, 0, 0));

        assertEquals(1790, world.coneRange(210, 0, 0, HALF_CONE, MAX_RANGE, self), EPS);
    }

    @Test
    void coneSeesItsOwnBodyWhenNotTold() {
        GeometryClient world = world(box(2000, -3000, 2100, 3000));
        world.addBody(P3DX, new Pose2D(0, 0, 0));

        // the apex lies on the body's front face
        assertEquals(0, world.coneRange(210, 0, 0, HALF_CONE, MAX_RANGE, -1), EPS);
    }

    @ParameterizedTest
    @ValueSource(doubles = {0, -0.1, Math.PI / 2, 2, Double.NaN})
    void coneRejectsABadHalfAngle(double halfAngle) {
        GeometryClient world = world();

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> world.coneRange(0, 0, 0, halfAngle, MAX_RANGE, -1));

        assertEquals(halfAngle + " was supplied for halfAngle: it must be between 0 and π/2", e.getMessage());
    }
}
