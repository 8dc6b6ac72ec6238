package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import robosim.protocol.Command;
import robosim.protocol.LaserReading;

/** The SICK laser against hand-computed ranges in a literal world. */
class LaserTest {
    @ParameterizedTest(name = "increment {0}°")
    @ValueSource(doubles = {1.0, 0.5})
    void aScanOfAWallAheadMatchesHandComputedRanges(double increment) {
        // a long wall whose face is x = 3000; the robot at (1000, 5000) facing +x; the p3dx laser sits
        // 18 mm ahead of the centre, so at (1018, 5000): a beam at angle a meets the face at
        // 1982 / cos a, and sees nothing within 8000 mm beyond about ±75.6°
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(3000, -30000, 3100, 40000)),
                Worlds.robot("r", 1000, 5000, 0, Worlds.p3dxWithLaser(18, 0, 0))));
        sim.step(Map.of("r", List.of(new Command.ConfigureLaser(true, increment, 8000))));
        int[] scan = sim.state("r").get(LaserReading.PART).ranges();
        int n = (int) Math.round(180 / increment) + 1;
        assertEquals(n, scan.length);
        for (int i = 0; i < n; i++) {
            double a = Math.toRadians(-90 + i * increment);
            double r = Math.cos(a) > 1e-9 ? 1982 / Math.cos(a) : Double.POSITIVE_INFINITY;
            long expected = r <= 8000 ? Math.round(r) : 8000;
            assertEquals(expected, scan[i], 0, "beam " + i + " at " + Math.toDegrees(a) + "°");
        }
        assertEquals(1982, scan[n / 2], "straight ahead");
    }

    @ParameterizedTest(name = "laser heading {0}°")
    @ValueSource(doubles = {90, -90})
    void theMountingPoseTurnsTheScan(double laserTh) {
        // a laser mounted facing left sees the wall at y = 7000 straight ahead of itself
        Simulation sim = new Simulation(Worlds.world(10000, 10000,
                List.of(Worlds.box(0, 7000, 10000, 7100), Worlds.box(0, 2900, 10000, 3000)),
                Worlds.robot("r", 5000, 5000, 0, Worlds.p3dxWithLaser(0, 100, laserTh))));
        sim.step(Map.of("r", List.of(new Command.ConfigureLaser(true, 1, 8000))));
        int[] scan = sim.state("r").get(LaserReading.PART).ranges();
        assertEquals(laserTh > 0 ? 7000 - 5100 : 5100 - 3000, scan[90]);
    }

    @ParameterizedTest(name = "max range {0}")
    @ValueSource(ints = {1000, 1500})
    void nothingWithinTheMaximumRangeReadsTheMaximum(int max) {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(3000, 0, 3100, 10000)),
                Worlds.robot("r", 1000, 5000, 0, Worlds.p3dxWithLaser(18, 0, 0))));
        sim.step(Map.of("r", List.of(new Command.ConfigureLaser(true, 1, max))));
        assertEquals(max, sim.state("r").get(LaserReading.PART).ranges()[90]);
    }

    @ParameterizedTest(name = "on={0}")
    @ValueSource(booleans = {false})
    void aLaserSwitchedOffSendsNoScan(boolean on) {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(), Worlds.robot("r", 1000, 5000, 0)));
        sim.step(Map.of("r", List.of(new Command.ConfigureLaser(true, 1, 8000))));
        assertEquals(181, sim.state("r").get(LaserReading.PART).ranges().length);
        sim.step(Map.of("r", List.of(new Command.ConfigureLaser(on, 1, 8000))));
        assertEquals(0, sim.state("r").get(LaserReading.PART).ranges().length);
    }
}
