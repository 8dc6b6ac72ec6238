package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** ArMath's calls beyond the angles and rounding of ArMathTest, with ARIA's edge cases (ariaUtil.h). */
class ArMathAriaTest {
    @ParameterizedTest
    @CsvSource({"180, 180", "-180, 180", "540, 180", "-540, 180", "190, -170", "-190, 170", "360, 0", "-360, 0",
        "720.5, 0.5", "179.999, 179.999", "-179.999, -179.999", "1e9, -80"})
    void fixAngleWrapsIntoMinus180To180(double angle, double fixed) {
        assertEquals(fixed, ArMath.fixAngle(angle), 1e-6);
    }

    @Test
    void fixAngleOfNaNOrInfinityIsNaN() {
        assertTrue(Double.isNaN(ArMath.fixAngle(Double.NaN)));
        assertTrue(Double.isNaN(ArMath.fixAngle(Double.POSITIVE_INFINITY)));
    }

    @ParameterizedTest
    @CsvSource({"0, 0", "180, 180", "-90, 270", "-180, 180", "360, 0", "-360, 0", "719, 359", "-1, 359", "359.5, 359.5"})
    void fixAngle360WrapsInto0To360(double angle, double fixed) {
        assertEquals(fixed, ArMath.fixAngle360(angle), 1e-9);
    }

    @Test
    void subAngleSignSaysWhichWayToTurn() {
        assertEquals(20, ArMath.subAngle(-170, 170), 1e-9, "from 170 to -170 is 20 degrees counter-clockwise");
        assertEquals(-20, ArMath.subAngle(170, -170), 1e-9);
        assertEquals(180, ArMath.subAngle(0, 180), 1e-9, "half a turn is +180, never -180");
        assertEquals(180, ArMath.subAngle(180, 0), 1e-9);
    }

    @Test
    void trigonometryIsInDegrees() {
        assertEquals(0.5, ArMath.cos(60), 1e-12);
        assertEquals(0.5, ArMath.sin(30), 1e-12);
        assertEquals(1, ArMath.tan(45), 1e-12);
        assertEquals(-1, ArMath.cos(180), 1e-12);
        assertEquals(135, ArMath.atan2(1, -1), 1e-12);
        assertEquals(-90, ArMath.atan2(-5, 0), 1e-12);
        assertEquals(-180, ArMath.atan2(-0.0, -1), 1e-12, "atan2's own range, not normalised");
    }

    @Test
    void fabsIsTheAbsoluteValue() {
        assertEquals(3.5, ArMath.fabs(-3.5));
        assertEquals(3.5, ArMath.fabs(3.5));
    }

    @ParameterizedTest
    @CsvSource({"2.5, 2", "2.51, 3", "-2.5, -3", "0.5, 0", "32766.6, 32767", "40000, 32767", "-40000, -32768",
        "-32768.4, -32768"})
    void roundShortIsRoundIntsRuleHeldToAShort(double val, short rounded) {
        assertEquals(rounded, ArMath.roundShort(val));
    }

    @Test
    void roundShortOfNaNIsZero() {
        assertEquals(0, ArMath.roundShort(Double.NaN));
    }

    @Test
    void pointRotateTurnsThePointByMinusTh() {
        double[] p = {1000, 0};
        ArMath.pointRotate(p, 90);
        assertArrayEquals(new double[] {0, -1000}, p, 1e-9);
        double[] q = {0, 1000};
        ArMath.pointRotate(q, 90);
        assertArrayEquals(new double[] {1000, 0}, q, 1e-9);
        assertThrows(IllegalArgumentException.class, () -> ArMath.pointRotate(new double[3], 10));
    }

    @Test
    void squaredDistanceIsTheSquareOfTheDistance() {
        assertEquals(25, ArMath.squaredDistanceBetween(1, 2, 4, 6));
        assertEquals(ArMath.distanceBetween(3, -7, 11, 2) * ArMath.distanceBetween(3, -7, 11, 2),
                ArMath.squaredDistanceBetween(3, -7, 11, 2), 1e-9);
    }

    @Test
    void distanceWithNaNIsNaN() {
        assertTrue(Double.isNaN(ArMath.distanceBetween(Double.NaN, 0, 0, 0)));
        assertTrue(Double.isNaN(ArMath.squaredDistanceBetween(0, 0, 0, Double.NaN)));
    }

    @Test
    void log2UsesAriasRoundedConstant() {
        assertEquals(Math.log10(8) / 0.3010303, ArMath.log2(8), 0);
        assertEquals(3, ArMath.log2(8), 1e-5);
        assertEquals(2, (int) ArMath.log2(8), "ARIA's rounded log10(2) puts log2(8) just under 3");
        assertEquals(0, ArMath.log2(1), 0);
        assertTrue(Double.isNaN(ArMath.log2(-1)));
    }

    @Test
    void epsilonIsTheDoublesMachineEpsilon() {
        assertEquals(2.220446049250313e-16, ArMath.epsilon(), 0);
    }

    @Test
    void compareFloatsAllowsEpsilon() {
        assertTrue(ArMath.compareFloats(0.1 + 0.2, 0.3), "one ulp of floating-point error");
        assertFalse(ArMath.compareFloats(1.0, 1.0 + 1e-12));
        assertTrue(ArMath.compareFloats(1.0, 1.04, 0.05));
        assertTrue(ArMath.compareFloats(1.0, 1.5, 0.5), "a difference of exactly epsilon is equal");
        assertFalse(ArMath.compareFloats(1.0, 1.06, 0.05));
        assertFalse(ArMath.compareFloats(Double.NaN, Double.NaN, 1));
        assertTrue(ArMath.compareFloats(1e-320, 2e-320, 0), "differences below the smallest normal double count as equal");
    }

    @Test
    void isNanAndIsFinite() {
        assertTrue(ArMath.isNan(Double.NaN));
        assertFalse(ArMath.isNan(1));
        assertTrue(ArMath.isFinite(1e308));
        assertFalse(ArMath.isFinite(Double.NEGATIVE_INFINITY));
        assertFalse(ArMath.isFinite(Double.NaN));
    }

    @Test
    void randomStaysBelowRandMax() {
        assertEquals(2147483648L, ArMath.getRandMax());
        for (int i = 0; i < 1000; i++) {
            long r = ArMath.random();
            assertTrue(r >= 0 && r < ArMath.getRandMax(), "drew " + r);
        }
    }

    @Test
    void randomInRangeIsFromMUpToButNotIncludingN() {
        boolean sawLow = false;
        for (int i = 0; i < 2000; i++) {
            long r = ArMath.randomInRange(5, 8);
            assertTrue(r >= 5 && r < 8, "drew " + r);
            sawLow |= r == 5;
        }
        assertTrue(sawLow);
        assertEquals(10, ArMath.randomInRange(10, 11), "a range of one value");
    }

    @Test
    void randomInRangeKeepsAriasArithmeticForNBelowM() {
        for (int i = 0; i < 1000; i++) {
            long r = ArMath.randomInRange(10, 7); // 10 + random() % -3: 10, 11 or 12
            assertTrue(r >= 10 && r < 13, "drew " + r);
        }
    }

    @Test
    void randomInRangeOfAnEmptyRangeThrows() {
        assertThrows(IllegalArgumentException.class, () -> ArMath.randomInRange(4, 4));
    }

    @Test
    void aConnectedRobotDrawsFromItsOwnGeneratorSeededByRunSeedAndName() {
        ConnectedRobot a = new ConnectedRobot("p3dx");
        Random ga = ArMath.generatorFor(a);
        assertSame(ga, ArMath.generatorFor(a), "one generator per robot");
        Random expected = new Random(ArMath.robotSeed(a.getRunSeed(), a.getName()));
        for (int i = 0; i < 5; i++) {
            assertEquals(expected.nextInt(), ga.nextInt());
        }
        assertSame(ArMath.generatorFor(null), ArMath.generatorFor(Cycles.p3dxRobot()),
                "no robot, or one not connected: the fixed-seed generator");
    }

    @Test
    void robotSeedsDifferByRunAndByName() {
        assertEquals(ArMath.robotSeed(7, "a"), ArMath.robotSeed(7, "a"));
        assertNotEquals(ArMath.robotSeed(7, "a"), ArMath.robotSeed(7, "b"));
        assertNotEquals(ArMath.robotSeed(7, "a"), ArMath.robotSeed(8, "a"));
    }

    @Test
    void angleBetweenWrapsThrough180AndExcludesItsBounds() {
        assertTrue(ArMath.angleBetween(180, 170, -170));
        assertTrue(ArMath.angleBetween(-175, 170, -170));
        assertFalse(ArMath.angleBetween(0, 170, -170));
        assertFalse(ArMath.angleBetween(170, 170, -170));
        assertFalse(ArMath.angleBetween(10, 10, 10));
    }
}
