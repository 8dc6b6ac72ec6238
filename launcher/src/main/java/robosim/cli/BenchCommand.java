package robosim.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robosim.bench.CodecBench;
import robosim.bench.CoreBench;
import robosim.bench.GoldFinderBench;
import robosim.bench.LaserBench;
import robosim.bench.StepRateBench;
import robosim.params.RobotParameterFiles;

/** {@code robosim bench}: prints the benchmark figures kept in docs/BENCHMARKS.md. */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = "Measure steps per second in the grid world (Environment in this JVM, robots in one client JVM, over TCP), the wire formats and the laser.")
final class BenchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--robots", split = ",", defaultValue = "1,10,100", paramLabel = "N[,N...]",
            description = "robot counts to measure; default ${DEFAULT-VALUE}")
    List<Integer> robots;

    @Option(names = "--steps", defaultValue = "600", paramLabel = "N", description = "steps per measurement; default ${DEFAULT-VALUE}")
    long steps;

    @Option(names = "--out", defaultValue = "out/bench", paramLabel = "DIR", description = "where worlds and client logs go; default ${DEFAULT-VALUE}")
    Path out;

    @Option(names = "--skip-codec", description = "do not measure the wire formats")
    boolean skipCodec;

    @Option(names = "--skip-laser", description = "do not measure the laser")
    boolean skipLaser;

    @Option(names = "--goldfinder", description = "instead: steps to find the gold with 1, 2, 4 and 8 robots over --mazes generated 10x10 mazes")
    boolean goldfinder;

    @Option(names = "--mazes", defaultValue = "20", paramLabel = "N", description = "mazes for --goldfinder; default ${DEFAULT-VALUE}")
    int mazes;

    @Option(names = "--repeat", defaultValue = "1", paramLabel = "R", description = "runs per robot count; the median is printed too; default ${DEFAULT-VALUE}")
    int repeat;

    @Override
    public Integer call() throws Exception {
        PrintWriter o = spec.commandLine().getOut();
        for (int n : robots) {
            if (n < 1 || n > 400) {
                spec.commandLine().getErr().println("robosim bench: " + n + " was supplied for --robots: counts are 1 to 400");
                return 2;
            }
        }
        if (repeat < 1) {
            spec.commandLine().getErr().println("robosim bench: " + repeat + " was supplied for --repeat: it must be at least 1");
            return 2;
        }
        if (steps < 10) {
            spec.commandLine().getErr().println("robosim bench: " + steps + " was supplied for --steps: it must be at least 10");
            return 2;
        }
        Path root = RobotParameterFiles.root();
        Path p3dx = RobotParameterFiles.resolve("p3dx").toAbsolutePath();
        Files.createDirectories(out);
        o.printf(Locale.ROOT, "bench: %d cores, Java %s, %s%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.version"), System.getProperty("os.arch"));
        if (goldfinder) {
            long limit = 60_000;
            GoldFinderBench.print(o, GoldFinderBench.run(List.of(1, 2, 4, 8), mazes, 10, limit, out.resolve("mazes"), p3dx), limit);
            return 0;
        }
        if (!skipCodec) {
            CodecBench.print(o, CodecBench.run(20_000));
        }
        if (!skipLaser) {
            Path cluttered = root.resolve("testLoadFiles/environment/cluttered-room.xml");
            LaserBench.print(o, LaserBench.run(cluttered, 1.0, 5000));
            LaserBench.print(o, LaserBench.run(cluttered, 0.5, 5000));
        }
        for (int n : robots) {
            o.printf(Locale.ROOT, "core only (no TCP, one thread): ");
            StepRateBench.print(o, CoreBench.run(n, steps, out, p3dx));
            double[] rates = new double[repeat];
            for (int r = 0; r < repeat; r++) {
                StepRateBench.Result tcp = StepRateBench.run(n, steps, out, p3dx);
                StepRateBench.print(o, tcp);
                rates[r] = tcp.realtimeFactor();
            }
            if (repeat > 1) {
                java.util.Arrays.sort(rates);
                o.printf(Locale.ROOT, "step rate: %3d robots  median of %d runs: %.1fx real time (range %.1f to %.1f)%n",
                        n, repeat, rates[repeat / 2], rates[0], rates[repeat - 1]);
            }
        }
        return 0;
    }
}
