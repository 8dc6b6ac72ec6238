package robosim.panel.model;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class PaceTest {
    @ParameterizedTest
    @CsvSource({"0, max", "1, 1x", "2, 2x", "3, 2x", "0.3, 0.25x", "50, 100x", "0.01, 0.1x", "1000, 100x"})
    void aStatusPaceShowsOnTheNearestStop(double factor, String label) {
        assertEquals(label, Pace.STOPS.get(Pace.nearest(factor)).label());
    }
}
