package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class Pose2DTest {
    private static final double EPS = 1e-9;

    private static void assertPose(double x, double y, double th, Pose2D actual) {
        assertEquals(x, actual.x(), EPS, "x");
        assertEquals(y, actual.y(), EPS, "y");
        assertEquals(th, actual.th(), EPS, "th");
    }

    @Test
    void straightAlongX() {
        assertPose(150, 200, 0, new Pose2D(100, 200, 0).advance(50, 0));
    }

    @Test
    void straightAlongTheHeading() {
        assertPose(0, 100, Math.PI / 2, new Pose2D(0, 0, Math.PI / 2).advance(100, 0));
    }

    @Test
    void straightAtThirtyDegrees() {
        // cos 30° = √3/2, sin 30° = 1/2
        assertPose(10 + 1000 * Math.sqrt(3) / 2, 20 + 500, Math.PI / 6,
                new Pose2D(10, 20, Math.PI / 6).advance(1000, 0));
    }

    @Test
    void straightBackwards() {
        assertPose(-100, 0, 0, new Pose2D(0, 0, 0).advance(-100, 0));
    }

    @Test
    void quarterCircleLeft() {
        // radius 1000 about (0, 1000)
        assertPose(1000, 1000, Math.PI / 2, new Pose2D(0, 0, 0).advance(Math.PI / 2 * 1000, Math.PI / 2));
    }

    @Test
    void quarterCircleRight() {
        // radius 1000 about (0, -1000)
        assertPose(1000, -1000, -Math.PI / 2, new Pose2D(0, 0, 0).advance(Math.PI / 2 * 1000, -Math.PI / 2));
    }

    @Test
    void quarterCircleLeftFromHeadingNorth() {
        // radius 1000 about (-1000, 0)
        assertPose(-1000, 1000, Math.PI, new Pose2D(0, 0, Math.PI / 2).advance(Math.PI / 2 * 1000, Math.PI / 2));
    }

    @Test
    void quarterCircleBackwardsWhileTurningLeft() {
        // backing up while the heading grows: the path bends towards -y, about the centre (0, -1000)
        assertPose(-1000, -1000, Math.PI / 2, new Pose2D(0, 0, 0).advance(-Math.PI / 2 * 1000, Math.PI / 2));
    }

    @Test
    void halfCircle() {
        assertPose(0, 1000, Math.PI, new Pose2D(0, 0, 0).advance(Math.PI * 500, Math.PI));
    }

    @Test
    void quarterCircleFromAnOffsetPose() {
        assertPose(2500, 3500, Math.PI / 2, new Pose2D(2000, 3000, 0).advance(Math.PI / 2 * 500, Math.PI / 2));
    }

    @Test
    void turnInPlaceKeepsThePosition() {
        assertPose(300, -400, 1.0 + Math.PI / 2, new Pose2D(300, -400, 1.0).advance(0, Math.PI / 2));
    }

    @Test
    void headingIsNotWrapped() {
        assertPose(0, 0, 3 * Math.PI, new Pose2D(0, 0, Math.PI).advance(0, 2 * Math.PI));
    }

    @Test
    void tinyRotationIsNearlyStraight() {
        Pose2D p = new Pose2D(0, 0, 0).advance(1000, 1e-6);

        // the sagitta of a 1000 mm arc turning 1e-6 rad is 0.0005 mm
        assertEquals(1000, p.x(), 1e-6);
        assertEquals(0.0005, p.y(), 1e-6);
    }

    @Test
    void worldCoordinatesOfALocalPoint() {
        Pose2D pose = new Pose2D(100, 200, Math.PI / 2);

        // 10 mm forward and 5 mm left of a robot heading +y is 5 mm towards -x and 10 mm towards +y
        assertEquals(95, pose.worldX(10, 5), EPS);
        assertEquals(210, pose.worldY(10, 5), EPS);
    }
}
