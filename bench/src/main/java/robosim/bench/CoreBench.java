package robosim.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import robosim.env.core.Simulation;
import robosim.env.net.PooledParallel;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Command;

/**
 * The simulation core alone, in this JVM, on the grid world: the same per-step robot logic as
 * {@link BenchRobots}, without TCP or robot threads (the sensors read on one thread, or on as many
 * as asked). The gap to {@link StepRateBench} is what the wire and the lockstep handoffs cost.
 */
public final class CoreBench {
    private CoreBench() {
    }

    /**
     * @param robots    robots in the grid
     * @param steps     steps to run
     * @param dir       where to write the world
     * @param robotFile the p3dx parameter file
     * @return the figures
     * @throws IOException if the world cannot be written
     */
    public static StepRateBench.Result run(int robots, long steps, Path dir, Path robotFile) throws IOException {
        return run(robots, steps, dir, robotFile, 1);
    }

    /**
     * @param robots    robots in the grid
     * @param steps     steps to run
     * @param dir       where to write the world
     * @param robotFile the p3dx parameter file
     * @param threads   threads that read the sensors, as the Environment's {@code --threads}; 1 for
     *                  the calling thread alone
     * @return the figures
     * @throws IOException if the world cannot be written
     */
    public static StepRateBench.Result run(int robots, long steps, Path dir, Path robotFile, int threads)
            throws IOException {
        try (PooledParallel parallel = new PooledParallel(threads)) {
            Simulation sim = new Simulation(WorldReader.read(GridWorld.write(robots, dir, robotFile)), 1, parallel);
            return run(sim, robots, steps);
        }
    }

    private static StepRateBench.Result run(Simulation sim, int robots, long steps) {
        List<String> names = sim.robotNames();
        long t0 = System.nanoTime();
        for (long s = 0; s < steps; s++) {
            Map<String, List<Command>> commands = new HashMap<>();
            for (String name : names) {
                int[] sonar = sim.state(name).sonar();
                boolean blocked = BenchRobots.blocked(i -> sonar[i], sonar.length);
                commands.put(name, List.of(new Command.SetVel(blocked ? 0 : 300), new Command.SetRotVel(blocked ? 30 : 0)));
            }
            sim.step(commands);
        }
        return new StepRateBench.Result(robots, steps, (System.nanoTime() - t0) / 1e9);
    }
}
