package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class ArPoseTest {
    @Test
    void headingIsNormalisedWhenSet() {
        assertEquals(-170, new ArPose(0, 0, 190).getTh(), 1e-9);
        assertEquals(180, new ArPose(0, 0, -180).getTh(), 1e-9);
        ArPose p = new ArPose();
        p.setTh(540);
        assertEquals(180, p.getTh(), 1e-9);
    }

    @Test
    void distanceAndAngleTo() {
        ArPose a = new ArPose(100, 100, 0);
        ArPose b = new ArPose(400, 500, 90);
        assertEquals(500, a.findDistanceTo(b), 1e-9);
        assertEquals(Math.toDegrees(Math.atan2(400, 300)), a.findAngleTo(b), 1e-9);
        assertEquals(-180 + Math.toDegrees(Math.atan2(400, 300)), b.findAngleTo(a), 1e-9);
    }

    @Test
    void fixAngleMatchesAria() {
        assertEquals(180, ArMath.fixAngle(-180), 1e-9);
        assertEquals(180, ArMath.fixAngle(180), 1e-9);
        assertEquals(-90, ArMath.fixAngle(270), 1e-9);
        assertEquals(0, ArMath.fixAngle(720), 1e-9);
    }

    @Test
    void setPoseAndSetYChangeItInPlaceAndTheSquaredDistanceSparesTheRoot() {
        ArPose p = new ArPose();
        p.setPose(30, 40, 370);
        assertEquals(30, p.getX());
        assertEquals(40, p.getY());
        assertEquals(10, p.getTh(), 1e-9, "normalised");
        p.setY(-40);
        assertEquals(-40, p.getY());
        assertEquals(30, p.getX(), "the rest unchanged");
        ArPose origin = new ArPose();
        assertEquals(2500, p.squaredFindDistanceTo(origin), 1e-9);
        assertEquals(p.findDistanceTo(origin) * p.findDistanceTo(origin), origin.squaredFindDistanceTo(p), 1e-9);
    }
}
