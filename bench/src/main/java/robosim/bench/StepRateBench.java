package robosim.bench;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import robosim.env.core.Simulation;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;

/**
 * Steps per second, as fast as possible, in the grid world: the Environment in this JVM, the robots
 * in one client JVM of their own, over TCP on loopback.
 */
public final class StepRateBench {
    /** One measurement. */
    public record Result(int robots, long steps, double seconds) {
        /** @return steps per second */
        public double stepsPerSecond() {
            return steps / seconds;
        }

        /** @return how many times faster than real time, with 100 ms steps */
        public double realtimeFactor() {
            return stepsPerSecond() * 0.1;
        }
    }

    private StepRateBench() {
    }

    /**
     * Runs one measurement.
     *
     * @param robots    robots in the grid
     * @param steps     steps to run
     * @param dir       where to write the world
     * @param robotFile the p3dx parameter file
     * @return the figures
     * @throws IOException          if the world or the client JVM fail
     * @throws InterruptedException if interrupted
     */
    public static Result run(int robots, long steps, Path dir, Path robotFile) throws IOException, InterruptedException {
        Path world = GridWorld.write(robots, dir, robotFile);
        Simulation sim = new Simulation(WorldReader.read(world));
        ServerOptions options = ServerOptions.loopback().withMaxSteps(steps);
        try (EnvironmentServer server = new EnvironmentServer(sim, options)) {
            server.bind();
            Process client = clientJvm(server.robotPort(), robots, robotFile, dir.resolve("client-" + robots + ".log"));
            try {
                RunReport report = server.run();
                if (report.steps() != steps) {
                    throw new IllegalStateException("the run ended early: " + report.endReason()
                            + " (see " + dir.resolve("client-" + robots + ".log") + ")");
                }
                return new Result(robots, report.steps(), report.wallNanos() / 1e9);
            } finally {
                if (!client.waitFor(30, TimeUnit.SECONDS)) {
                    client.destroyForcibly().waitFor(5, TimeUnit.SECONDS);
                }
            }
        }
    }

    private static Process clientJvm(int port, int robots, Path robotFile, Path log) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"),
                BenchRobots.class.getName(), "127.0.0.1", Integer.toString(port), Integer.toString(robots),
                robotFile.toAbsolutePath().toString()));
        return new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
    }

    /**
     * Prints a result as one line.
     *
     * @param out where
     * @param r   the result
     */
    public static void print(PrintWriter out, Result r) {
        out.printf(Locale.ROOT, "step rate: %3d robots  %6d steps in %7.2f s  %8.1f steps/s  %6.1fx real time%n",
                r.robots(), r.steps(), r.seconds(), r.stepsPerSecond(), r.realtimeFactor());
        out.flush();
    }
}
