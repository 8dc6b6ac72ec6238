package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ArMathTest {
    @ParameterizedTest
    @CsvSource({"170, 20, -170", "-170, -20, 170", "90, 90, 180", "-90, -90, 180", "0, 720, 0", "45, -30, 15"})
    void addAngleFixesTheSumIntoMinus180To180(double a, double b, double sum) {
        assertEquals(sum, ArMath.addAngle(a, b), 1e-12);
    }

    @Test
    void degreesAndRadiansConvertBothWays() {
        assertEquals(Math.PI / 2, ArMath.degToRad(90), 1e-15);
        assertEquals(-180, ArMath.radToDeg(-Math.PI), 1e-12);
        assertEquals(33.3, ArMath.radToDeg(ArMath.degToRad(33.3)), 1e-12);
    }

    @Test
    void distanceBetweenIsTheStraightLine() {
        assertEquals(5000, ArMath.distanceBetween(1000, 2000, 4000, 6000), 1e-9);
        assertEquals(0, ArMath.distanceBetween(-7, 3, -7, 3));
    }

    @ParameterizedTest
    @CsvSource({"2.5, 2", "2.51, 3", "-2.5, -3", "-2.4, -2", "0.51, 1", "0.5, 0", "7, 7", "-7, -7"})
    void roundIntAddsFortyNineHundredthsAndFloorsAsAriaDoes(double val, int rounded) {
        assertEquals(rounded, ArMath.roundInt(val));
    }

    @Test
    void roundIntHoldsTheResultWithinAnIntsRange() {
        assertEquals(Integer.MAX_VALUE, ArMath.roundInt(1e12));
        assertEquals(Integer.MIN_VALUE, ArMath.roundInt(-1e12));
        assertEquals(0, ArMath.roundInt(Double.NaN));
    }

    @ParameterizedTest
    @CsvSource({"10, 30, -20", "170, -170, -20", "-170, 170, 20", "90, -90, 180", "0, 0, 0"})
    void subAngleIsTheDifferenceFixedIntoMinus180To180(double a, double b, double difference) {
        assertEquals(difference, ArMath.subAngle(a, b), 1e-9);
    }
}
