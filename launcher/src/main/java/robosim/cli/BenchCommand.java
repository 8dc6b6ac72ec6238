package robosim.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.logging.Level;
import java.util.logging.Logger;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robosim.bench.BenchSensors;
import robosim.bench.CodecBench;
import robosim.bench.CoreBench;
import robosim.bench.Floors;
import robosim.bench.GoldFinderBench;
import robosim.bench.InProcessBench;
import robosim.bench.LaserBench;
import robosim.bench.MapLoadBench;
import robosim.bench.PioneerFloodBench;
import robosim.bench.StepRateBench;
import robosim.env.net.ServerOptions;
import robosim.hw.EnvironmentLinks;
import robosim.hw.RobotThreads;
import robosim.params.RobotParameterFiles;

/** {@code robosim bench}: prints the benchmark figures kept in docs/BENCHMARKS.md. */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = "Measure load-and-connect time and steps per second in the grid world (Environment in this JVM,"
                + " robots in client JVMs, over TCP; and the core alone), the wire formats and the laser.")
final class BenchCommand implements Callable<Integer> {
    /** The most robots one measurement may have. */
    static final int MAX_ROBOTS = 5000;
    /** The most client JVMs one measurement may start. */
    static final int MAX_CLIENTS = 64;
    /** The most points of a generated map. */
    static final int MAX_MAP_POINTS = 5_000_000;

    /** The Environment's per-connection lines, quieted while measuring: thousands of them say nothing. */
    private static final Logger NET_LOG = Logger.getLogger("robosim.env.net");

    @Spec
    CommandSpec spec;

    @Option(names = "--robots", split = ",", defaultValue = "1,10,100", paramLabel = "N",
            description = OptionTexts.ROBOTS + "; the counts to measure, comma-separated, 1 to " + MAX_ROBOTS
                    + " each; default ${DEFAULT-VALUE}")
    List<Integer> robots;

    @Option(names = "--sensors", split = ",", defaultValue = "sonar", paramLabel = "S",
            description = "what every robot reads each step: sonar (its 16 sonars) or laser (the sonars and a SICK laser,"
                    + " 181 beams at 1 deg, 8000 mm); repeatable; default ${DEFAULT-VALUE}")
    List<String> sensors;

    @Option(names = "--links", split = ",", defaultValue = "tcp,in-process", paramLabel = "L",
            description = "how the robots reach the Environment in the step-rate runs: tcp (client JVMs, --clients) or"
                    + " in-process (threads of this JVM, no TCP); a comma list; default ${DEFAULT-VALUE}")
    List<String> links;

    @Option(names = "--clients", defaultValue = "1", paramLabel = "K",
            description = "client JVMs to spread the robots over, 1 to " + MAX_CLIENTS + " (never more than the robots);"
                    + " default ${DEFAULT-VALUE}")
    int clients;

    @Option(names = "--threads", paramLabel = "N",
            description = OptionTexts.THREADS + "; in the core-only runs and in the"
                    + " Environment (its --threads); default: the machine's processors")
    Integer threads;

    @Option(names = "--steps", defaultValue = "600", paramLabel = "N", description = OptionTexts.STEPS
            + "; in each measurement; default ${DEFAULT-VALUE}")
    long steps;

    @Option(names = "--out-dir", defaultValue = "out/bench", paramLabel = "DIR", description = OptionTexts.OUT_DIR
            + "; worlds and client logs; default ${DEFAULT-VALUE}")
    Path out;

    @Option(names = "--out", hidden = true, paramLabel = "DIR", description = OptionTexts.OLD_NAME + "--out-dir")
    Path oldOut;

    @Option(names = "--skip-codec", description = "do not measure the wire formats")
    boolean skipCodec;

    @Option(names = "--skip-laser", description = "do not measure the laser's cost alone")
    boolean skipLaser;

    @Option(names = "--skip-core", description = "do not run the core alone before the runs over TCP (so this JVM"
            + " holds only the Environment and its memory figures are the Environment's alone)")
    boolean skipCore;

    @Option(names = "--goldfinder", description = "instead: steps to find the gold with teams of --teams robots over --mazes generated mazes")
    boolean goldfinder;

    @Option(names = "--teams", split = ",", defaultValue = "1,2,4,8", paramLabel = "N",
            description = "team sizes for --goldfinder, compared with the first; default ${DEFAULT-VALUE}")
    List<Integer> teams;

    @Option(names = "--maze-size", defaultValue = "10", paramLabel = "CELLS",
            description = "cells across and up of --goldfinder's mazes; default ${DEFAULT-VALUE}")
    int mazeSize;

    @Option(names = "--message-loss", defaultValue = "0", paramLabel = "P",
            description = "for --goldfinder: the chance, 0 to 1, that a message is lost on its way; default ${DEFAULT-VALUE}")
    double loss;

    @Option(names = "--message-latency", defaultValue = "1", paramLabel = "STEPS",
            description = "for --goldfinder: steps a message takes, at least 1; default ${DEFAULT-VALUE}")
    int latency;

    @Option(names = "--step-limit", defaultValue = "60000", paramLabel = "N",
            description = "for --goldfinder: the step limit of each run; default ${DEFAULT-VALUE}")
    long stepLimit;

    @Option(names = "--mazes", defaultValue = "20", paramLabel = "N", description = "mazes for --goldfinder; default ${DEFAULT-VALUE}")
    int mazes;

    @Option(names = "--sweep", paramLabel = "FILE", description = "instead: an experiment's sweep, runs per minute"
            + " with its robots on the in-process link and in JVMs of their own (--sweep-links), --sweep-parallel at"
            + " once, and each run's time beyond its simulation")
    Path sweep;

    @Option(names = "--sweep-parallel", defaultValue = "2", paramLabel = "N",
            description = "for --sweep: runs at once; default ${DEFAULT-VALUE}")
    int sweepParallel;

    @Option(names = "--sweep-links", split = ",", defaultValue = "in-process,jvm", paramLabel = "L",
            description = "for --sweep: the links to measure, in-process and jvm; default ${DEFAULT-VALUE}")
    List<String> sweepLinks;

    @Option(names = "--first-maze", defaultValue = "1", paramLabel = "SEED",
            description = "for --goldfinder: the first maze's seed; the mazes are seeds SEED to SEED + --mazes - 1"
                    + " (a maze never tuned on is a fresh one); default ${DEFAULT-VALUE}")
    int firstMaze;

    @Option(names = "--floors", description = "instead: what a step cannot go below here, measured without RoboSim:"
            + " a hand-off between two threads (platform, and virtual where the JDK has them) and a loopback TCP round trip")
    boolean floors;

    @Option(names = "--pioneer-flood", description = "instead: the run's steps per second while an ARIA client on a"
            + " Pioneer port behaves and while it floods its port with connections and commands (--robots' first count,"
            + " at least 2; each rate over --flood-seconds)")
    boolean pioneerFlood;

    @Option(names = "--flood-seconds", defaultValue = "5", paramLabel = "S",
            description = "for --pioneer-flood: how long each rate is measured, 1 to 60; default ${DEFAULT-VALUE}")
    double floodSeconds;

    @Option(names = "--map-load", description = "instead: time reading a generated map of --map-points points"
            + " (--map-kind, or --map FILE) into a world, building the simulation on it, and a laser scan against it")
    boolean mapLoad;

    @Option(names = "--map-points", defaultValue = "100000", paramLabel = "N",
            description = "points of the map --map-load generates, 1000 to " + MAX_MAP_POINTS + "; default ${DEFAULT-VALUE}")
    int mapPoints;

    @Option(names = "--map-kind", defaultValue = "building", paramLabel = "KIND",
            description = "what --map-load generates: building (a scanned building: rooms, slanted walls, furniture)"
                    + " or random (points scattered uniformly over the same square, whole mm: hardly any merge);"
                    + " default ${DEFAULT-VALUE}")
    String mapKind;

    @Option(names = "--map-read-only", description = "for --map-load: time the reading into a world alone (and the"
            + " heap the world keeps), not the simulation built on it nor its steps")
    boolean mapReadOnly;

    @Option(names = "--map", paramLabel = "FILE", description = "an ARIA map for --map-load to time instead of a generated one")
    Path map;

    @Option(names = "--heap-every", defaultValue = "0", paramLabel = "N",
            description = "in each run over TCP, sample every N steps each JVM's heap after its last garbage collection"
                    + " (none forced) and print the samples with its memory figures; 0 for none; default ${DEFAULT-VALUE}")
    long heapEvery;

    @Option(names = "--rates-every", defaultValue = "0", paramLabel = "N",
            description = "print, after each run, for every N steps from the first on: the steps per second, and each"
                    + " JVM's CPU time and heap allocated per step (the core alone's, and over TCP the Environment's and"
                    + " each client's); 0 for none; default ${DEFAULT-VALUE}")
    long window;

    // not --window, which shows a run in a window in viewer and replay
    @Option(names = "--window", hidden = true, paramLabel = "N", description = OptionTexts.OLD_NAME + "--rates-every")
    Long oldWindow;

    @Option(names = "--repeat", defaultValue = "1", paramLabel = "R",
            description = "runs over TCP per robot count and sensors; the median and range are printed too; default ${DEFAULT-VALUE}")
    int repeat;

    @Override
    public Integer call() throws Exception {
        out = oldOut != null ? oldOut : out;
        window = oldWindow != null ? oldWindow : window;
        PrintWriter o = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        for (int n : robots) {
            if (n < 1 || n > MAX_ROBOTS) {
                throw new ParameterException(spec.commandLine(),
                        n + " was supplied for --robots: counts are 1 to " + MAX_ROBOTS);
            }
        }
        Set<BenchSensors> sensorSets = new LinkedHashSet<>();
        for (String s : sensors) {
            Optional<BenchSensors> named = BenchSensors.named(s);
            if (named.isEmpty()) {
                throw new ParameterException(spec.commandLine(),
                        s + " was supplied for --sensors: sensors are sonar or laser");
            }
            sensorSets.add(named.get());
        }
        for (String l : links) {
            if (!l.equals("tcp") && !l.equals("in-process")) {
                throw new ParameterException(spec.commandLine(),
                        l + " was supplied for --links: links are tcp or in-process");
            }
        }
        if (clients < 1 || clients > MAX_CLIENTS) {
            throw new ParameterException(spec.commandLine(),
                    clients + " was supplied for --clients: client JVMs are 1 to " + MAX_CLIENTS);
        }
        if (repeat < 1) {
            throw new ParameterException(spec.commandLine(),
                    repeat + " was supplied for --repeat: it must be at least 1");
        }
        if (heapEvery < 0) {
            throw new ParameterException(spec.commandLine(),
                    heapEvery + " was supplied for --heap-every: it must be 0 (none) or more");
        }
        if (window < 0) {
            throw new ParameterException(spec.commandLine(),
                    window + " was supplied for --rates-every: it must be 0 (none) or more");
        }
        int sensingThreads = threads != null ? threads : ServerOptions.defaultThreads();
        if (sensingThreads < 1) {
            throw new ParameterException(spec.commandLine(),
                    sensingThreads + " was supplied for --threads: it must be at least 1");
        }
        if (steps < 10) {
            throw new ParameterException(spec.commandLine(),
                    steps + " was supplied for --steps: it must be at least 10");
        }
        checkModeOptions();
        Path root = RobotParameterFiles.root();
        Path p3dx = RobotParameterFiles.resolve("p3dx").toAbsolutePath();
        Files.createDirectories(out);
        o.printf(Locale.ROOT, "bench: %d cores, Java %s, %s, %d sensing threads, robot threads %s, links %s%n",
                Runtime.getRuntime().availableProcessors(), System.getProperty("java.version"),
                System.getProperty("os.arch"), sensingThreads, RobotThreads.virtual() ? "virtual" : "platform",
                EnvironmentLinks.Mode.configured().name().toLowerCase(Locale.ROOT));
        if (sweep != null) {
            for (int r = 0; r < repeat; r++) {
                SweepBench.print(o, sweep, SweepBench.run(sweep, out, sweepParallel, sweepLinks));
            }
            return 0;
        }
        if (floors) {
            for (int r = 0; r < repeat; r++) {
                Floors.print(o, Floors.measure(50_000));
            }
            return 0;
        }
        if (pioneerFlood) {
            int n = robots.get(0);
            Level quiet = NET_LOG.getLevel();
            NET_LOG.setLevel(Level.WARNING);
            try {
                for (int r = 0; r < repeat; r++) {
                    PioneerFloodBench.print(o, PioneerFloodBench.run(n, floodSeconds, out.resolve("pioneer-flood"), p3dx));
                }
            } finally {
                NET_LOG.setLevel(quiet);
            }
            return 0;
        }
        if (mapLoad) {
            Path file = map != null ? map : mapKind.equals("random")
                    ? MapLoadBench.generateRandom(out.resolve("random-" + mapPoints + ".map"), mapPoints)
                    : MapLoadBench.generate(out.resolve("scan-" + mapPoints + ".map"), mapPoints);
            for (int r = 0; r < repeat; r++) {
                MapLoadBench.print(o, MapLoadBench.run(file, 5, mapReadOnly));
            }
            return 0;
        }
        if (goldfinder) {
            GoldFinderBench.print(o, GoldFinderBench.run(teams, firstMaze, mazes, mazeSize, stepLimit, out.resolve("mazes"), p3dx,
                    loss, latency), stepLimit);
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
        StepRateBench.printLegend(o);
        Level level = NET_LOG.getLevel();
        NET_LOG.setLevel(Level.WARNING);
        try {
            for (BenchSensors s : sensorSets) {
                for (int n : robots) {
                    if (!skipCore) {
                        StepRateBench.print(o, CoreBench.run(n, s, steps, out, p3dx, sensingThreads, window));
                    }
                    for (String link : new LinkedHashSet<>(links)) {
                        List<StepRateBench.Result> runs = new ArrayList<>();
                        for (int r = 0; r < repeat; r++) {
                            StepRateBench.Result run = link.equals("tcp")
                                    ? StepRateBench.run(n, s, clients, steps, out, p3dx, sensingThreads, heapEvery, window)
                                    : InProcessBench.run(n, s, steps, out, p3dx, sensingThreads, window);
                            StepRateBench.print(o, run);
                            runs.add(run);
                        }
                        if (repeat > 1) {
                            StepRateBench.printMedian(o, runs);
                        }
                    }
                }
            }
        } catch (IllegalStateException e) {
            err.println("robosim bench: " + e.getMessage());
            return 1;
        } finally {
            NET_LOG.setLevel(level);
        }
        return 0;
    }

    /** The options of the one measurement asked for instead of the default ones, checked before anything is measured. */
    private void checkModeOptions() {
        if (sweep != null) {
            if (sweepParallel < 1) {
                throw new ParameterException(spec.commandLine(), sweepParallel + " was supplied for --sweep-parallel:"
                        + " it must be at least 1");
            }
            for (String l : sweepLinks) {
                if (!l.equals("in-process") && !l.equals("jvm")) {
                    throw new ParameterException(spec.commandLine(), "'" + l + "' was supplied for --sweep-links: links"
                            + " are in-process and jvm");
                }
            }
        }
        if (pioneerFlood) {
            int n = robots.get(0);
            if (n < 2) {
                throw new ParameterException(spec.commandLine(),
                        n + " was supplied for --robots: --pioneer-flood needs at least 2 robots");
            }
            if (!(floodSeconds >= 1 && floodSeconds <= 60)) {
                throw new ParameterException(spec.commandLine(),
                        floodSeconds + " was supplied for --flood-seconds: it must be from 1 to 60");
            }
        }
        if (mapLoad) {
            if (mapPoints < 1000 || mapPoints > MAX_MAP_POINTS) {
                throw new ParameterException(spec.commandLine(),
                        mapPoints + " was supplied for --map-points: it must be from 1000 to " + MAX_MAP_POINTS);
            }
            if (!mapKind.equals("building") && !mapKind.equals("random")) {
                throw new ParameterException(spec.commandLine(),
                        mapKind + " was supplied for --map-kind: kinds are building or random");
            }
        }
        if (goldfinder) {
            try {
                ServerOptions.requireAtLeast("--maze-size", mazeSize, 2);
                ServerOptions.requireAtLeast("--message-latency", latency, 1);
                ServerOptions.requireAtLeast("--step-limit", stepLimit, 1);
                ServerOptions.requireAtLeast("--first-maze", firstMaze, 1);
                ServerOptions.requireAtLeast("--mazes", mazes, 1);
                for (int t : teams) {
                    ServerOptions.requireAtLeast("--teams", t, 1);
                }
                if (!(loss >= 0 && loss <= 1)) {
                    throw new IllegalArgumentException(loss + " was supplied for --message-loss: it must be from 0 to 1");
                }
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage());
            }
        }
    }
}
