package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** ArPose's calls as ARIA's (ariaUtil.h): setters, operators as methods, polygons. */
class ArPoseAriaTest {
    @Test
    void setPoseWithoutAHeadingSetsItToZero() {
        ArPose p = new ArPose(1, 2, 45);
        p.setPose(3, 4);
        assertEquals(3, p.getX());
        assertEquals(4, p.getY());
        assertEquals(0, p.getTh());
        assertEquals(0, new ArPose(5, 6).getTh());
    }

    @Test
    void setPoseFromAPoseCopiesIt() {
        ArPose src = new ArPose(7, 8, 190);
        ArPose p = new ArPose();
        p.setPose(src);
        assertEquals(7, p.getX());
        assertEquals(8, p.getY());
        assertEquals(-170, p.getTh(), 1e-12);
        src.setX(0);
        assertEquals(7, p.getX(), "a copy, not a view");
        assertEquals(-170, new ArPose(src).getTh(), 1e-12);
    }

    @Test
    void radiansAreNormalisedToo() {
        ArPose p = new ArPose();
        p.setThRad(3 * Math.PI / 2);
        assertEquals(-90, p.getTh(), 1e-12);
        assertEquals(-Math.PI / 2, p.getThRad(), 1e-12);
    }

    @Test
    void getPoseFillsTheArraysGivenAndSkipsNulls() {
        ArPose p = new ArPose(1, 2, 3);
        double[] x = {9};
        double[] th = {9};
        p.getPose(x, null, th);
        assertEquals(1, x[0]);
        assertEquals(3, th[0]);
    }

    @Test
    void addAndSubtractNormaliseTheHeading() {
        ArPose a = new ArPose(100, 200, 170);
        ArPose b = new ArPose(10, -20, 20);
        ArPose sum = a.add(b);
        assertEquals(110, sum.getX());
        assertEquals(180, sum.getY());
        assertEquals(-170, sum.getTh(), 1e-12);
        ArPose diff = new ArPose(0, 0, -170).subtract(new ArPose(1, 1, 20));
        assertEquals(-1, diff.getX());
        assertEquals(170, diff.getTh(), 1e-12);
        assertEquals(170, a.getTh(), "add leaves its operands");
    }

    @Test
    void inPlaceFormsChangeThisPoseAndReturnIt() {
        ArPose a = new ArPose(1, 1, 90);
        assertSame(a, a.addInPlace(new ArPose(1, 2, 100)));
        assertEquals(2, a.getX());
        assertEquals(3, a.getY());
        assertEquals(-170, a.getTh(), 1e-12);
        assertSame(a, a.subtractInPlace(new ArPose(2, 3, 20)));
        assertEquals(0, a.getX());
        assertEquals(170, a.getTh(), 1e-12);
    }

    @Test
    void ariasEqualityAllowsEpsilonAndItsInequalityIsStrict() {
        ArPose a = new ArPose(0, 0, 0);
        assertTrue(a.isEqual(new ArPose(1e-17, 0, 0)));
        assertFalse(a.isNotEqual(new ArPose(1e-17, 0, 0)));
        assertFalse(a.isEqual(new ArPose(1e-10, 0, 0)));
        assertTrue(a.isNotEqual(new ArPose(0, 0, 1e-10)));
        ArPose atEpsilon = new ArPose(ArMath.epsilon(), 0, 0);
        assertFalse(a.isEqual(atEpsilon), "a difference of exactly epsilon is not equal...");
        assertFalse(a.isNotEqual(atEpsilon), "...nor unequal, as in ARIA");
    }

    @Test
    void lessThanSortsByXThenYThenHeading() {
        assertTrue(new ArPose(1, 9, 9).isLessThan(new ArPose(2, 0, 0)));
        assertTrue(new ArPose(1, 1, 9).isLessThan(new ArPose(1, 2, 0)));
        assertTrue(new ArPose(1, 1, 1).isLessThan(new ArPose(1, 1, 2)));
        assertFalse(new ArPose(1, 1, 1).isLessThan(new ArPose(1, 1, 1)));
        assertFalse(new ArPose(2, 0, 0).isLessThan(new ArPose(1, 9, 9)));
    }

    @Test
    void equalsIsExactAndAgreesWithHashCode() {
        assertEquals(new ArPose(1, 2, 3), new ArPose(1, 2, 3));
        assertEquals(new ArPose(1, 2, 3).hashCode(), new ArPose(1, 2, 3).hashCode());
        assertEquals(new ArPose(0.0, 0, 0), new ArPose(-0.0, 0, 0));
        assertEquals(new ArPose(0.0, 0, 0).hashCode(), new ArPose(-0.0, 0, 0).hashCode());
        assertNotEquals(new ArPose(1, 2, 3), new ArPose(1, 2, 3.0000001));
        ArPose nan = new ArPose(Double.NaN, 0, 0);
        assertEquals(nan, nan);
    }

    @Test
    void staticDistanceAndComparisons() {
        assertEquals(5, ArPose.distanceBetween(new ArPose(0, 0), new ArPose(3, 4)));
        assertTrue(ArPose.compareX(new ArPose(1, 5), new ArPose(2, 0)));
        assertFalse(ArPose.compareX(new ArPose(2, 0), new ArPose(2, 5)));
        assertTrue(ArPose.compareY(new ArPose(5, 1), new ArPose(0, 2)));
        assertFalse(ArPose.compareY(new ArPose(5, 2), new ArPose(0, 2)));
    }

    @Test
    void insidePolygonByTheEvenOddRule() {
        List<ArPose> square = List.of(new ArPose(0, 0), new ArPose(100, 0), new ArPose(100, 100), new ArPose(0, 100));
        assertTrue(new ArPose(50, 50).isInsidePolygon(square));
        assertFalse(new ArPose(150, 50).isInsidePolygon(square));
        assertFalse(new ArPose(-1, 50).isInsidePolygon(square));
        // a U shape: the notch is outside
        List<ArPose> u = List.of(new ArPose(0, 0), new ArPose(300, 0), new ArPose(300, 300), new ArPose(200, 300),
                new ArPose(200, 100), new ArPose(100, 100), new ArPose(100, 300), new ArPose(0, 300));
        assertFalse(new ArPose(150, 200).isInsidePolygon(u));
        assertTrue(new ArPose(50, 200).isInsidePolygon(u));
        assertTrue(new ArPose(150, 50).isInsidePolygon(u));
        assertFalse(new ArPose(0, 0).isInsidePolygon(List.of()), "no vertices, nothing inside");
    }

    @Test
    void findAngleToIsNormalisedAndZeroToItself() {
        assertEquals(180, new ArPose(0, -0.0).findAngleTo(new ArPose(-1, -0.0)), 1e-12);
        assertEquals(0, new ArPose(5, 5).findAngleTo(new ArPose(5, 5)), 0);
        assertEquals(-45, new ArPose(0, 0).findAngleTo(new ArPose(1, -1)), 1e-12);
    }
}
