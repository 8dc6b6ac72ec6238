package robosim.scout;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The Nomad's units against millimetres and degrees, both ways. */
class NomadUnitsTest {
    @ParameterizedTest
    @CsvSource({"0, 0", "2.54, 1", "254, 100", "1000, 394", "-254, -100", "1.26, 0", "1.27, 1", "-1.28, -1"})
    void millimetresToTenthsOfAnInch(double mm, long tenths) {
        assertEquals(tenths, NomadUnits.mmToTenthInch(mm));
    }

    @ParameterizedTest
    @CsvSource({"0, 0", "1, 2.54", "100, 254", "-394, -1000.76"})
    void tenthsOfAnInchToMillimetres(long tenths, double mm) {
        assertEquals(mm, NomadUnits.tenthInchToMm(tenths), 1e-9);
    }

    @ParameterizedTest
    @CsvSource({"0, 0", "90, 900", "0.04, 0", "0.05, 1", "-22.5, -225", "359.9, 3599"})
    void degreesToTenthsOfADegree(double degrees, long tenths) {
        assertEquals(tenths, NomadUnits.degToTenthDeg(degrees));
    }

    @ParameterizedTest
    @CsvSource({"0, 0", "900, 90", "-225, -22.5", "3599, 359.9"})
    void tenthsOfADegreeToDegrees(long tenths, double degrees) {
        assertEquals(degrees, NomadUnits.tenthDegToDeg(tenths), 1e-12);
    }

    @ParameterizedTest
    @CsvSource({"0, 0", "90, 900", "-90, 2700", "180, 1800", "-180, 1800", "359.96, 0", "720.5, 5", "-0.04, 0"})
    void headingsRunFrom0To3599(double degrees, long tenths) {
        assertEquals(tenths, NomadUnits.headingToTenthDeg(degrees));
    }

    @ParameterizedTest
    @CsvSource({"0, 0", "25.4, 1", "1000, 39", "6477, 255", "6500, 255", "100000, 255", "-5, 0", "12.6, 0", "12.7, 1"})
    void sonarRangesAreWholeInchesUpTo255(double mm, long inches) {
        assertEquals(inches, NomadUnits.sonarMmToInches(mm));
    }

    @Test
    void conversionsRoundTrip() {
        for (long t = -5000; t <= 5000; t += 37) {
            assertEquals(t, NomadUnits.mmToTenthInch(NomadUnits.tenthInchToMm(t)));
            assertEquals(t, NomadUnits.degToTenthDeg(NomadUnits.tenthDegToDeg(t)));
        }
        for (long in = 0; in <= 255; in++) {
            assertEquals(in, NomadUnits.sonarMmToInches(NomadUnits.inchesToMm(in)));
        }
    }
}
