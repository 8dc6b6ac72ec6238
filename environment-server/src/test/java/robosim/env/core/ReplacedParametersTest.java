package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.env.world.HeatSource;
import robosim.env.world.Noise;
import robosim.env.world.Obstacle;
import robosim.env.world.RobotSpec;
import robosim.env.world.World;
import robosim.params.ParameterFileReader;
import robosim.protocol.Command;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotParameters;
import robosim.protocol.TimeStep;

/**
 * Robots that replace their parameters one after another, with their states and snapshots asked
 * for in between as the Environment does, end up exactly where a simulation that started with
 * those parameters is: the same bodies, readings and noise, step after step.
 */
class ReplacedParametersTest {
    private static final int SIDE = 8;
    private static final double CELL = 2500;

    private static RobotParameters params(String file) {
        return ParameterFileReader.read(Worlds.root().resolve("testLoadFiles/robots/" + file));
    }

    /** A grid of robots close enough to see each other; {@code replaced} gives some robots other parameters. */
    private static World grid(Map<Integer, RobotParameters> replaced) {
        List<Obstacle> obstacles = new ArrayList<>();
        double size = SIDE * CELL;
        obstacles.add(Worlds.box(0, 0, size, 100));
        obstacles.add(Worlds.box(0, size - 100, size, size));
        obstacles.add(Worlds.box(0, 0, 100, size));
        obstacles.add(Worlds.box(size - 100, 0, size, size));
        obstacles.add(Worlds.box(3000, 3000, 3400, 3400));
        RobotSpec[] robots = new RobotSpec[SIDE * SIDE];
        for (int k = 0; k < robots.length; k++) {
            robots[k] = Worlds.robot("r" + k, (k % SIDE) * CELL + CELL / 2, (k / SIDE) * CELL + CELL / 2,
                    (53 * k) % 360, replaced.getOrDefault(k, Worlds.p3dx()));
        }
        return Worlds.world(size, size, obstacles, List.of(new HeatSource(9000, 9000, 30, 1)), new Noise(25, 10, 0.03),
                robots);
    }

    private static void assertSame(Simulation expected, Simulation actual, String when) {
        MessageCodec codec = new MessageCodec();
        assertArrayEquals(codec.encode(expected.snapshot()), codec.encode(actual.snapshot()), "snapshot " + when);
        for (String name : expected.robotNames()) {
            assertArrayEquals(codec.encode(new TimeStep(1, 0, expected.state(name))),
                    codec.encode(new TimeStep(1, 0, actual.state(name))), name + " " + when);
            assertEquals(expected.summary(name), actual.summary(name), name + " " + when);
        }
    }

    @Test
    void replacingParametersOneByOneIsStartingWithThem() {
        RobotParameters p3at = params("p3at.p");
        RobotParameters scout = params("scout.p");
        Map<Integer, RobotParameters> replaced = Map.of(9, p3at, 10, scout, 18, p3at, 27, p3at, 63, scout, 0, scout);
        Simulation started = new Simulation(grid(replaced), 5);
        Simulation replacing = new Simulation(grid(Map.of()), 5);
        // as robots say hello: each is sent its state at once; a viewer attaches half way
        for (int k : new int[] {9, 10, 18}) {
            replacing.useParameters("r" + k, replaced.get(k));
            replacing.state("r" + k);
            replacing.state("r" + (k + 1));
        }
        replacing.snapshot();
        replacing.useParameters("r11", Worlds.p3dx());
        for (int k : new int[] {27, 63, 0}) {
            replacing.useParameters("r" + k, replaced.get(k));
            replacing.state("r" + k);
        }
        assertSame(started, replacing, "before step 1");
        for (int step = 1; step <= 30; step++) {
            Map<String, List<Command>> cs = new java.util.HashMap<>();
            for (int k = 0; k < SIDE * SIDE; k++) {
                cs.put("r" + k, List.of(new Command.SetVel(100 + 37 * ((k + step) % 9)), new Command.SetRotVel((k % 5) * 6 - 12)));
            }
            started.step(cs);
            replacing.step(cs);
            assertSame(started, replacing, "after step " + step);
        }
    }

    @Test
    void aRefusedBodyChangesNothing() {
        Simulation sim = new Simulation(grid(Map.of()), 5);
        Simulation untouched = new Simulation(grid(Map.of()), 5);
        sim.state("r9");
        RobotParameters huge = new RobotParameters("Pioneer", "huge", 3000, 5000, 2500, 2500, 1000, 100, 300, 300,
                100, 100, 0.0056, 5000, Worlds.p3dx().sonarUnits());
        assertThrows(IllegalArgumentException.class, () -> sim.useParameters("r9", huge));
        assertSame(untouched, sim, "after a refusal");
    }
}
