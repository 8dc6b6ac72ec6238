package robosim.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The parameters panel's rows. */
class ParameterRowsTest {
    private final List<ParameterRows.Row> rows = ParameterRows.of("test.p", Fixtures.robot(1200, 300));

    private String value(String name) {
        return rows.stream().filter(r -> r.name().equals(name)).findFirst().orElseThrow().value();
    }

    @Test
    void theFileComesFirst() {
        assertEquals(new ParameterRows.Row("file", "test.p"), rows.get(0));
    }

    @Test
    void limitsAreShownWithTheirUnits() {
        assertEquals("1200 mm/s", value("MaxVelocity"));
        assertEquals("300 deg/s", value("MaxRVelocity"));
        assertEquals("0.0056", value("DiffConvFactor"));
    }

    @Test
    void eachSonarHasARow() {
        assertEquals("2", value("SonarNum"));
        assertEquals("x 0 mm, y 100 mm, th 90°", value("SonarUnit 1"));
    }
}
