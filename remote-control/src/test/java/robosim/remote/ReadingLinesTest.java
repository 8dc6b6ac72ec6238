package robosim.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** What the readings panel says. */
class ReadingLinesTest {
    @Test
    void beforeTheFirstStepItSaysItWaits() {
        assertEquals(List.of("waiting for the first step"), ReadingLines.of(null));
    }

    @Test
    void aStepShowsPoseVelocitiesStallAndEachSensor() {
        Readings r = new Readings(42, 4200, 1500.4, -20, 90, 300, -12.5, true, true,
                Readings.sonarRays(Fixtures.robot(1000, 100), new int[] {900, 300}), true,
                List.of(new Readings.Point(1, 2)), new Readings.Heat(0.5, 30, 1200), 8000);
        assertEquals(List.of(
                "step 42, t = 4.2 s",
                "pose x 1500 mm, y -20 mm, th 90.0°",
                "vel 300 mm/s, rotVel -12.5 deg/s",
                "STALLED: a collision stopped the robot",
                "sonar: 2 rays, nearest 300 mm",
                "laser: on, 1 hits in range",
                "heat: 0.50 at bearing 30°, 1200 mm"), ReadingLines.of(r));
    }

    @Test
    void sensorsSwitchedOffSaySo() {
        Readings r = new Readings(1, 100, 0, 0, 0, 0, 0, false, false, List.of(), false, List.of(), null, 5000);
        List<String> lines = ReadingLines.of(r);
        assertEquals("stall: no", lines.get(3));
        assertEquals(List.of("sonar: off", "laser: off", "heat: off"), lines.subList(4, 7));
    }
}
