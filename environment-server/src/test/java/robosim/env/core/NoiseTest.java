package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.env.world.Noise;
import robosim.env.world.World;
import robosim.protocol.Command;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;

/** Seeded noise: the same seed repeats exactly; the noise has the configured spread. */
class NoiseTest {
    private static World room(Noise noise) {
        // a 4 m room: every sonar and beam sees a wall well within range
        return Worlds.world(4000, 4000, List.of(Worlds.box(0, 0, 4000, 100), Worlds.box(0, 3900, 4000, 4000),
                        Worlds.box(0, 0, 100, 4000), Worlds.box(3900, 0, 4000, 4000)), List.of(), noise,
                Worlds.robot("r", 2000, 2000, 20, Worlds.p3dxWithLaser(18, 0, 0)));
    }

    private static int[][] readings(Noise noise, long seed, int steps) {
        Simulation sim = new Simulation(room(noise), seed);
        sim.step(Map.of("r", List.of(new Command.ConfigureLaser(true, 1, 8000))));
        int[][] out = new int[steps][];
        for (int i = 0; i < steps; i++) {
            sim.step(Map.of());
            RobotState s = sim.state("r");
            int[] both = new int[s.get(SonarReading.PART).ranges().length + s.get(LaserReading.PART).ranges().length];
            System.arraycopy(s.get(SonarReading.PART).ranges(), 0, both, 0, s.get(SonarReading.PART).ranges().length);
            System.arraycopy(s.get(LaserReading.PART).ranges(), 0, both, s.get(SonarReading.PART).ranges().length, s.get(LaserReading.PART).ranges().length);
            out[i] = both;
        }
        return out;
    }

    @Test
    void theSameSeedGivesIdenticalNoisyReadings() {
        Noise noise = new Noise(20, 10, 0);
        int[][] a = readings(noise, 42, 50);
        int[][] b = readings(noise, 42, 50);
        for (int i = 0; i < a.length; i++) {
            assertArrayEquals(a[i], b[i], "step " + i);
        }
        assertNotEquals(readings(noise, 43, 1)[0][0] + "," + readings(noise, 43, 1)[0][20],
                a[0][0] + "," + a[0][20], "another seed gives other noise");
    }

    @Test
    void noisyReadingsDifferFromTheTruthWithTheConfiguredSpread() {
        int steps = 200;
        int[][] truth = readings(Noise.NONE, 1, 1);
        int[][] noisy = readings(new Noise(20, 10, 0), 7, steps);
        double[] sonarSpread = spread(truth[0], noisy, 0, 16);
        double[] laserSpread = spread(truth[0], noisy, 16, 16 + 181);
        assertEquals(0, sonarSpread[0], 2.0, "sonar noise is unbiased");
        assertEquals(20, sonarSpread[1], 2.0, "sonar sigma 20 mm");
        assertEquals(0, laserSpread[0], 0.5, "laser noise is unbiased");
        assertEquals(10, laserSpread[1], 0.5, "laser sigma 10 mm");
    }

    /** Mean and standard deviation of noisy − true over every step, for readings from..to. */
    private static double[] spread(int[] truth, int[][] noisy, int from, int to) {
        double sum = 0;
        double sq = 0;
        int n = 0;
        for (int[] step : noisy) {
            for (int i = from; i < to; i++) {
                double e = step[i] - truth[i];
                sum += e;
                sq += e * e;
                n++;
            }
        }
        double mean = sum / n;
        return new double[] {mean, Math.sqrt(sq / n - mean * mean)};
    }

    @Test
    void odometryDriftsFromTheTruePoseAndTheControllerSteersByIt() {
        Simulation sim = new Simulation(Worlds.world(20000, 20000, List.of(), List.of(), new Noise(0, 0, 0.0075),
                Worlds.robot("r", 1000, 10000, 0)), 5);
        sim.step(Map.of("r", List.of(new Command.Move(8000))));
        for (int i = 0; i < 400; i++) {
            sim.step(Map.of());
        }
        RobotSummary s = sim.summary("r");
        double odoTravelled = Math.hypot(s.odoX() - 1000, s.odoY() - 10000);
        assertEquals(8000, odoTravelled, 40, "the move ends when the odometry says 8000 mm");
        double error = Math.hypot(s.x() - s.odoX(), s.y() - s.odoY());
        assertTrue(error > 1 && error < 400, "odometry drifted by " + error + " mm over 8 m");
        RobotState st = sim.state("r");
        assertEquals(s.odoX(), st.x(), 0.0, "the robot reads its odometry");
    }

    @Test
    void withoutNoiseOdometryIsTheTruePoseExactly() {
        Simulation sim = new Simulation(Worlds.world(20000, 20000, List.of(), Worlds.robot("r", 1000, 10000, 0)));
        sim.step(Map.of("r", List.of(new Command.SetVel(400), new Command.SetRotVel(7))));
        for (int i = 0; i < 100; i++) {
            sim.step(Map.of());
        }
        RobotSummary s = sim.summary("r");
        assertEquals(s.x(), s.odoX(), 0.0);
        assertEquals(s.y(), s.odoY(), 0.0);
        assertEquals(s.th(), s.odoTh(), 0.0);
    }
}
