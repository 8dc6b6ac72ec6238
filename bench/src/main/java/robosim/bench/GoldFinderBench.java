package robosim.bench;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import robosim.comms.CommsSettings;
import robosim.env.core.Simulation;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.World;
import robosim.env.world.maze.GoldBound;
import robosim.env.world.maze.Maze;
import robosim.env.world.maze.MazeWorldWriter;
import robosim.env.world.xml.WorldReader;
import robosim.examples.goldfinder.GoldFinder;

/**
 * Does cooperation pay? Steps until the gold is found, for teams of several sizes, over the same
 * generated mazes; the Environment in this JVM, the robots as threads of it, over TCP.
 */
public final class GoldFinderBench {
    private GoldFinderBench() {
    }

    /**
     * The steps each maze took one team size (−1: not found within the limit), and the lower bound
     * of each maze for that team ({@link GoldBound#steps}).
     */
    public record Result(int robots, long[] steps, long[] bounds) {
        /** @return the mean of the lower bounds */
        public double meanBound() {
            return Arrays.stream(bounds).average().orElse(Double.NaN);
        }

        /** @return the mean over the mazes where the gold was found */
        public double mean() {
            return Arrays.stream(steps).filter(s -> s >= 0).average().orElse(Double.NaN);
        }

        /** @return the median over the mazes where the gold was found */
        public double median() {
            long[] f = Arrays.stream(steps).filter(s -> s >= 0).sorted().toArray();
            return f.length == 0 ? Double.NaN : f[f.length / 2];
        }

        /** @return the mazes where the gold was found */
        public long found() {
            return Arrays.stream(steps).filter(s -> s >= 0).count();
        }
    }

    /**
     * @param teams     team sizes to compare
     * @param firstMaze the first maze's seed, at least 1
     * @param mazes     mazes (seeds firstMaze .. firstMaze + mazes - 1)
     * @param size      cells across and up
     * @param maxSteps  the step limit of a run
     * @param dir       where the mazes are written
     * @param robotFile the p3dx parameter file
     * @param loss      the chance that a message is lost on its way to each recipient, 0 to 1
     * @param latency   steps a message takes, at least 1
     * @return one result per team size
     * @throws IOException          if a maze cannot be written
     * @throws InterruptedException if interrupted
     */
    public static List<Result> run(List<Integer> teams, int firstMaze, int mazes, int size, long maxSteps, Path dir, Path robotFile,
                                   double loss, int latency) throws IOException, InterruptedException {
        Files.createDirectories(dir);
        int most = teams.stream().mapToInt(Integer::intValue).max().orElse(1);
        Result[] out = new Result[teams.size()];
        for (int t = 0; t < teams.size(); t++) {
            out[t] = new Result(teams.get(t), new long[mazes], new long[mazes]);
        }
        for (int m = 0; m < mazes; m++) {
            int seed = firstMaze + m;
            Path file = dir.resolve("maze-" + size + "-" + seed + ".xml");
            Maze maze = Maze.generate(size, size, seed);
            Files.writeString(file, MazeWorldWriter.write(maze, "maze-" + seed, CELL_SIZE,
                    most, robotFile.toAbsolutePath().toString()), StandardCharsets.UTF_8);
            World world = WorldReader.read(file);
            for (int t = 0; t < teams.size(); t++) {
                out[t].bounds()[m] = GoldBound.steps(world.withFirstRobots(teams.get(t)));
                out[t].steps()[m] = steps(world.withFirstRobots(teams.get(t)), seed, maxSteps, loss, latency);
            }
        }
        return List.of(out);
    }

    /** The benchmark mazes' cell size, mm. */
    static final int CELL_SIZE = 1500;

    private static long steps(World world, long seed, long maxSteps, double loss, int latency)
            throws IOException, InterruptedException {
        Simulation sim = new Simulation(world, seed);
        CommsSettings c = sim.commsSettings();
        sim.setCommsSettings(new CommsSettings(c.maxRange(), c.wallsBlock(), latency, loss, c.maxMessageBytes()));
        try (EnvironmentServer server = new EnvironmentServer(sim,
                ServerOptions.loopback().withMaxSteps(maxSteps))) {
            server.bind();
            List<Thread> team = GoldFinder.start("127.0.0.1", server.robotPort(), world.robots().size());
            RunReport report = server.run();
            for (Thread t : team) {
                t.join(10_000);
            }
            return report.find() == null ? -1 : report.find().step();
        }
    }

    /**
     * @param out     where
     * @param results the figures
     * @param maxSteps the step limit of each run
     */
    public static void print(PrintWriter out, List<Result> results, long maxSteps) {
        double alone = results.get(0).mean();
        for (Result r : results) {
            out.printf(Locale.ROOT, "goldfinder: %d robot(s): found in %d of %d mazes within %d steps; mean %.0f steps, median %.0f; %.2fx the first team's mean; per maze %s%n",
                    r.robots(), r.found(), r.steps().length, maxSteps, r.mean(), r.median(), r.mean() / alone,
                    Arrays.toString(r.steps()));
        }
        for (Result r : results) {
            out.printf(Locale.ROOT, "goldfinder: %d robot(s): lower bound (shortest path from the nearest robot, driven at top speed) mean %.0f steps, %.2fx the first team's mean; the team took %.2fx its bound; per maze %s%n",
                    r.robots(), r.meanBound(), r.meanBound() / alone, r.mean() / r.meanBound(), Arrays.toString(r.bounds()));
        }
        out.flush();
    }
}
