package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.env.world.HeatSource;
import robosim.env.world.Noise;
import robosim.protocol.Command;
import robosim.protocol.HeatReading;

/** The heat sensor: I·(1000/d)², within its field of view and range, blocked by walls. */
class HeatTest {
    private static HeatReading sense(double robotTh, double fov, double range, boolean wall, double... sources) {
        List<HeatSource> heat = new java.util.ArrayList<>();
        for (int i = 0; i < sources.length; i += 3) {
            heat.add(new HeatSource(sources[i], sources[i + 1], sources[i + 2], 1));
        }
        Simulation sim = new Simulation(Worlds.world(10000, 10000,
                wall ? List.of(Worlds.box(2000, 4000, 2100, 6000)) : List.of(), heat, Noise.NONE,
                Worlds.robot("r", 1000, 5000, robotTh)));
        sim.step(Map.of("r", List.of(new Command.ConfigureHeatSensor(true, fov, range))));
        return sim.state("r").get(HeatReading.PART);
    }

    @Test
    void aSourceAheadFallsOffWithTheSquareOfDistance() {
        HeatReading h = sense(0, 90, 5000, false, 3000, 5000, 10);
        assertEquals(10 * 0.25, h.intensity(), 1e-9, "10 at 1 m, 2 m away");
        assertEquals(0, h.bearing(), 1e-9);
        assertEquals(2000, h.distance(), 1e-9);
    }

    @Test
    void theBearingIsRelativeToTheHeading() {
        HeatReading h = sense(0, 180, 5000, false, 2000, 6000, 10);
        assertEquals(45, h.bearing(), 1e-9);
        assertEquals(10 * 1000 * 1000 / 2e6, h.intensity(), 1e-9);
    }

    @Test
    void theStrongestSourceInViewWins() {
        HeatReading h = sense(0, 180, 9000, false, 3000, 5000, 10, 1000, 8000, 200, 1500, 5000, 1);
        assertEquals(200 / 9.0, h.intensity(), 1e-9, "200 at 3 m beats 10 at 2 m and 1 at 0.5 m (4)");
    }

    @Test
    void outsideTheFieldOfViewOrRangeOrBehindAWallNothingIsSensed() {
        assertEquals(0, sense(180, 90, 5000, false, 3000, 5000, 10).intensity(), "behind the sensor");
        assertEquals(0, sense(0, 90, 1500, false, 3000, 5000, 10).intensity(), "beyond the range");
        assertEquals(0, sense(0, 90, 5000, true, 3000, 5000, 10).intensity(), "a wall in the way");
    }

    @Test
    void aSensorThatIsOffReportsNothing() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(), Worlds.robot("r", 1000, 5000, 0)));
        sim.step(Map.of());
        assertNull(sim.state("r").get(HeatReading.PART));
    }
}
