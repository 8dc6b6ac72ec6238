package robosim.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import robosim.env.core.Simulation;
import robosim.env.threads.PooledParallel;
import robosim.protocol.Command;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;

/**
 * The simulation core alone, in this JVM, on the grid world: the same per-step robot logic as
 * {@link BenchRobots}, without TCP or robot threads (the sensors read on one thread, or on as many as asked). The gap to {@link StepRateBench} is what the wire
 * and the lockstep handoffs cost.
 */
public final class CoreBench {
    private CoreBench() {
    }

    /**
     * @param robots    robots in the grid
     * @param sensors   what each robot reads: with the laser, every robot switches it on with its first
     *                  step's commands ({@code ConfigureLaser(true, 1, 8000)}), as the clients do
     * @param steps     steps to run
     * @param dir       where to write the world
     * @param robotFile the p3dx parameter file
     * @param threads   threads that read the sensors, as the Environment's {@code --threads}; 1 for
     *                  the calling thread alone
     * @param window    steps per window of this JVM's step rate, CPU time and allocation
     *                  ({@link StepWindows}); 0 for none
     * @return the figures; the load time is reading the world and building the Simulation
     * @throws IOException if the world cannot be written
     */
    public static StepRateBench.Result run(int robots, BenchSensors sensors, long steps, Path dir, Path robotFile,
                                           int threads, long window) throws IOException {
        try (PooledParallel parallel = new PooledParallel(threads)) {
            return run(robots, sensors, steps, GridWorld.write(robots, dir, robotFile), parallel, window);
        }
    }

    private static StepRateBench.Result run(int robots, BenchSensors sensors, long steps, Path worldFile,
                                            PooledParallel parallel, long window) {
        StepRateBench.Loaded loaded = StepRateBench.load(worldFile, parallel);
        Simulation sim = loaded.sim();
        List<String> names = sim.robotNames();
        StepWindows windows = window > 0
                ? new StepWindows(window, () -> names.stream().filter(n -> sim.state(n).stalled()).count()) : null;
        if (windows != null) {
            windows.at(0);
        }
        long start = System.nanoTime();
        for (long s = 0; s < steps; s++) {
            Map<String, List<Command>> commands = new HashMap<>();
            for (String name : names) {
                RobotState state = sim.state(name);
                int[] sonar = state.get(SonarReading.PART).ranges();
                int[] laser = state.get(LaserReading.PART).ranges();
                boolean blocked = BenchRobots.blocked(i -> sonar[i], sonar.length, laser);
                Command vel = new Command.SetVel(blocked ? 0 : 300);
                Command rot = new Command.SetRotVel(blocked ? 30 : 0);
                // the first step's commands are the clients' first: the motors enabled (a Pioneer's are
                // disabled when its program connects) and, with the laser, the laser switched on
                List<Command> first = new ArrayList<>(List.of(new Command.SetMotors(true)));
                if (sensors.laser()) {
                    first.add(new Command.ConfigureLaser(true, BenchSensors.LASER_INCREMENT, BenchSensors.LASER_MAX_RANGE));
                }
                first.add(vel);
                first.add(rot);
                commands.put(name, s == 0 ? first : List.of(vel, rot));
            }
            sim.step(commands);
            if (windows != null) {
                windows.at(s + 1);
            }
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        StepRateBench.Result result = new StepRateBench.Result("core", robots, sensors, 0, loaded.load(0), steps, seconds);
        if (windows == null) {
            return result;
        }
        windows.end(steps);
        return result.withWindows(List.of(new StepRateBench.WindowReport("env", windows.windows())));
    }
}
