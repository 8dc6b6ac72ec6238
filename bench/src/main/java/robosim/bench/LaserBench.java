package robosim.bench;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import robosim.env.core.Simulation;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Command;

/**
 * What the SICK laser costs, in one thread: the same world stepped with every robot's laser off
 * and on (robots turning in place so every scan differs); the difference is the laser's cost.
 */
public final class LaserBench {
    private LaserBench() {
    }

    /** One measurement: steps of all robots with the laser at an increment, against none. */
    public record Result(String world, int robots, double increment, int beams, long steps,
                         double secondsOff, double secondsOn) {
        /** @return microseconds one scan costs a robot per step */
        public double microsPerScan() {
            return (secondsOn - secondsOff) * 1e6 / (steps * robots);
        }

        /** @return laser rays cast per second of one core */
        public double raysPerSecond() {
            return beams * (double) robots * steps / (secondsOn - secondsOff);
        }
    }

    /**
     * @param worldFile a world file
     * @param increment 1 or 0.5 degrees
     * @param steps     steps per measurement
     * @return the figures
     */
    public static Result run(Path worldFile, double increment, long steps) {
        World world = WorldReader.read(worldFile);
        for (int warm = 0; warm < 3; warm++) { // the JIT compiles the ray code in the first runs
            time(world, steps, null);
            time(world, steps, increment);
        }
        double off = time(world, steps, null);
        double on = time(world, steps, increment);
        int beams = (int) Math.round(180 / increment) + 1;
        return new Result(world.name(), world.robots().size(), increment, beams, steps, off, on);
    }

    private static double time(World world, long steps, Double increment) {
        Simulation sim = new Simulation(world, 1);
        Map<String, List<Command>> first = new HashMap<>();
        for (String name : sim.robotNames()) {
            first.put(name, increment == null ? List.of(new Command.SetRotVel(20))
                    : List.of(new Command.SetRotVel(20), new Command.ConfigureLaser(true, increment, 8000)));
        }
        sim.step(first);
        long t0 = System.nanoTime();
        for (long s = 0; s < steps; s++) {
            sim.step(Map.of());
        }
        return (System.nanoTime() - t0) / 1e9;
    }

    /**
     * @param out where
     * @param r   the figures
     */
    public static void print(PrintWriter out, Result r) {
        out.printf(Locale.ROOT, "laser: %s, %d robots, %d beams at %.1f deg: %.1f us per scan per robot-step, %.2f million rays/s (one core)%n",
                r.world(), r.robots(), r.beams(), r.increment(), r.microsPerScan(), r.raysPerSecond() / 1e6);
        out.flush();
    }
}
