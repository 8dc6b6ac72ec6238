package robosim.env;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.comms.CommsSettings;
import robosim.env.core.Parallel;
import robosim.env.core.Simulation;
import robosim.env.threads.PooledParallel;
import robosim.env.world.HeatSource;
import robosim.env.world.Noise;
import robosim.env.world.Obstacle;
import robosim.env.world.RobotSpec;
import robosim.env.world.World;
import robosim.params.ParameterFileReader;
import robosim.protocol.Command;
import robosim.protocol.HeatReading;
import robosim.protocol.LaserReading;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;
import robosim.protocol.TimeStep;

/**
 * Reading the sensors on several threads changes nothing: a crowded world with noise, lasers, heat
 * sensors and messages, stepped with the same scripted commands by a serial simulation, one on a
 * pool of threads and one whose loop runs the robots backwards, gives the same state for every
 * robot and the same snapshot (bit for bit, as encoded for the wire) at every step.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class SerialParallelTest {
    private static final int COLUMNS = 20;
    private static final int ROWS = 15;
    private static final double CELL = 3000;
    private static final int STEPS = 100;

    /** Runs the indexes backwards on the calling thread: any order must do. */
    private static final Parallel BACKWARDS = (n, body) -> {
        for (int i = n - 1; i >= 0; i--) {
            body.accept(i);
        }
    };

    private static Path root() {
        Path p = Path.of("").toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        return p;
    }

    private static RobotParameters params(String file) {
        return ParameterFileReader.read(root().resolve("testLoadFiles/robots/" + file));
    }

    /**
     * 300 robots on a 20 × 15 grid of 3 m cells, a pillar in each cell (every fourth red, for the
     * cameras), heat sources, noise, lossy messages.
     */
    static World crowd() {
        RobotParameters p3dx = params("p3dx.p");
        RobotParameters scout = params("scout.p");
        Random rnd = new Random(300);
        double w = COLUMNS * CELL;
        double h = ROWS * CELL;
        List<Obstacle> obstacles = new ArrayList<>();
        obstacles.add(box(0, 0, w, 100, 1));
        obstacles.add(box(0, h - 100, w, h, 1));
        obstacles.add(box(0, 0, 100, h, 1));
        obstacles.add(box(w - 100, 0, w, h, 1));
        List<RobotSpec> robots = new ArrayList<>();
        for (int k = 0; k < COLUMNS * ROWS; k++) {
            double cx = (k % COLUMNS) * CELL + CELL / 2;
            double cy = (k / COLUMNS) * CELL + CELL / 2;
            double px = cx + 900 + rnd.nextInt(300);
            double py = cy + 900 + rnd.nextInt(300);
            Obstacle pillar = box(px - 250, py - 250, px + 250, py + 250, k + 2);
            obstacles.add(k % 4 == 0 ? new Obstacle(pillar.xy(), 500, k + 2, "#ff0000") : pillar);
            RobotParameters p = k % 7 == 3 ? scout : p3dx;
            robots.add(new RobotSpec("r" + k, k % 7 == 3 ? "scout" : "pioneer", cx + rnd.nextInt(400) - 200,
                    cy + rnd.nextInt(400) - 200, (37 * k) % 360, Path.of("robot.p"), p, k + 2));
        }
        HeatSource gold = new HeatSource(w * 0.7, h * 0.4, 50, 1);
        List<HeatSource> heat = List.of(new HeatSource(w * 0.2, h * 0.3, 20, 1), gold,
                new HeatSource(w * 0.5, h * 0.8, 35, 1));
        return new World("crowd", Path.of("crowd.xml"), w, h, 100, obstacles, robots, heat, new Noise(20, 10, 0.02),
                new CommsSettings(9000, true, 2, 0.2, 1000), gold);
    }

    private static Obstacle box(double x0, double y0, double x1, double y1, int line) {
        return new Obstacle(new double[] {x0, y0, x1, y0, x1, y1, x0, y1}, 500, line);
    }

    /** Commands for one step: scripted from a seeded stream, and reacting to the robots' sonars. */
    private static Map<String, List<Command>> commands(Simulation sim, Random script, long step) {
        Map<String, List<Command>> all = new HashMap<>();
        List<String> names = sim.robotNames();
        for (int k = 0; k < names.size(); k++) {
            String name = names.get(k);
            List<Command> cs = new ArrayList<>();
            if (step == 1 && k % 10 == 0) {
                cs.add(new Command.ConfigureLaser(true, k % 20 == 0 ? 1 : 0.5, 8000));
            }
            if (step == 1 && k % 6 == 1) {
                cs.add(new Command.ConfigureHeatSensor(true, 120, 30000));
            }
            if (step == 1 && k % 50 == 4) {
                cs.add(new Command.TrackColors(true));
                cs.add(new Command.AimPtz(k % 100 == 4 ? 30 : -30, -5, 200));
            }
            if (step == 1 && k % 5 == 2) {
                cs.add(new Command.JoinGroup("g" + (k % 3)));
            }
            int[] sonar = sim.state(name).get(SonarReading.PART).ranges();
            int nearest = Integer.MAX_VALUE;
            for (int r : sonar) {
                nearest = Math.min(nearest, r);
            }
            boolean blocked = nearest < 500;
            switch (script.nextInt(12)) {
                case 0 -> cs.add(new Command.SetHeading(script.nextInt(360)));
                case 1 -> cs.add(new Command.Move(script.nextInt(1500) - 500));
                case 2 -> cs.add(new Command.SetSonar(script.nextInt(4) != 0));
                case 3 -> cs.add(new Command.SendMessage(step * 1000 + k, Command.Addressing.GROUP, "g" + script.nextInt(3),
                        "text", "hello " + step));
                case 4 -> cs.add(new Command.SendMessage(step * 1000 + k, Command.Addressing.ROBOT,
                        names.get(script.nextInt(names.size())), "text", "to you"));
                case 5 -> cs.add(new Command.Say("step " + step));
                case 6 -> cs.add(new Command.SetVel2(script.nextInt(600) - 100, script.nextInt(600) - 100));
                case 7 -> cs.add(new Command.Stop());
                default -> {
                    cs.add(new Command.SetVel(blocked ? -100 : 200 + script.nextInt(700)));
                    cs.add(new Command.SetRotVel(blocked ? 40 : script.nextInt(60) - 30));
                }
            }
            if (!cs.isEmpty()) {
                all.put(name, cs);
            }
        }
        return all;
    }

    @Test
    void serialAndParallelSensingGiveTheSameRunBitForBit() {
        World world = crowd();
        MessageCodec codec = new MessageCodec();
        try (PooledParallel pool = new PooledParallel(3)) {
            List<Simulation> sims = List.of(new Simulation(world, 17), new Simulation(world, 17, pool),
                    new Simulation(world, 17, BACKWARDS));
            // as robots say hello: some bring other bodies; each is sent its state at once
            RobotParameters p3at = params("p3at.p");
            for (Simulation sim : sims) {
                for (int k = 40; k < 300; k += 37) {
                    sim.useParameters("r" + k, k % 7 == 3 ? params("scout.p") : p3at);
                    sim.state("r" + k);
                }
            }
            Simulation serial = sims.get(0);
            Random script = new Random(4);
            int lasers = 0;
            int heat = 0;
            for (long step = 0; step <= STEPS; step++) {
                if (step > 0) {
                    Map<String, List<Command>> cs = commands(serial, script, step);
                    for (Simulation sim : sims) {
                        sim.step(cs);
                    }
                }
                byte[] snapshot = codec.encode(serial.snapshot());
                for (Simulation sim : sims.subList(1, sims.size())) {
                    assertArrayEquals(snapshot, codec.encode(sim.snapshot()), "snapshot at step " + step);
                }
                for (String name : serial.robotNames()) {
                    RobotState s = serial.state(name);
                    byte[] expected = codec.encode(new TimeStep(step + 1, 0, s));
                    for (Simulation sim : sims.subList(1, sims.size())) {
                        assertArrayEquals(expected, codec.encode(new TimeStep(step + 1, 0, sim.state(name))),
                                name + " at step " + step);
                        assertEquals(serial.summary(name), sim.summary(name), name + " at step " + step);
                    }
                    if (step == STEPS) {
                        lasers += s.get(LaserReading.PART).ranges().length > 0 ? 1 : 0;
                        heat += s.get(HeatReading.PART) != null && s.get(HeatReading.PART).intensity() > 0 ? 1 : 0;
                    }
                }
            }
            assertTrue(lasers >= 25, "robots with a laser: " + lasers);
            assertTrue(heat > 0, "robots feeling heat: " + heat);
        }
    }
}
