package robosim.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robosim.env.core.RobotSummary;
import robosim.env.core.Simulation;
import robosim.env.net.Access;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.World;
import robosim.protocol.RunSecret;
import robosim.env.world.xml.WorldFileException;
import robosim.env.world.xml.WorldReader;
import robosim.examples.goldfinder.GoldFinder;
import robosim.viewer.draw.PngImageWriter;
import robosim.viewer.net.ViewerSummary;

/**
 * {@code robosim goldfinder}: the Environment on a maze, a team of Gold robots (threads of one JVM,
 * or a JVM each) and a viewer writing PNG images; prints who found the gold.
 */
@Command(name = "goldfinder", mixinStandardHelpOptions = true,
        description = "Run GoldFinder: a team of Pioneers searches WORLD for the gold. Exit 0 when found, 3 when the step limit ran out.")
final class GoldfinderCommand implements Callable<Integer> {
    /** The exit code when the step limit ran out before the gold was found. */
    static final int NOT_FOUND = 3;

    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "WORLD", description = "a maze world with <gold> (see robosim maze)")
    Path world;

    @Option(names = "--robots", defaultValue = "3", paramLabel = "N", description = "team size; default ${DEFAULT-VALUE}")
    int robots;

    @Option(names = "--separate-jvms", description = "run each robot in a JVM of its own")
    boolean separateJvms;

    @Option(names = "--seed", defaultValue = "1", description = "seed of the run and the team's tie-breaks; default ${DEFAULT-VALUE}")
    long seed;

    @Option(names = "--out", defaultValue = "out/goldfinder", paramLabel = "DIR", description = "frames and logs go here; default ${DEFAULT-VALUE}")
    Path out;

    @Option(names = "--max-steps", defaultValue = "20000", paramLabel = "N", description = "step limit; default ${DEFAULT-VALUE}")
    long maxSteps;

    @Option(names = "--every", defaultValue = "20", paramLabel = "K", description = "write a frame every K steps; default ${DEFAULT-VALUE}")
    int every;

    @Option(names = "--cell-size", defaultValue = "1500", paramLabel = "MM", description = "the maze's cell size; default ${DEFAULT-VALUE}")
    double cellSize;

    @Option(names = "--no-frames", description = "run without a viewer")
    boolean noFrames;

    @Mixin
    QuietOption quiet = new QuietOption();

    @Override
    public Integer call() throws Exception {
        PrintWriter o = spec.commandLine().getOut();
        World w;
        try {
            World full = WorldReader.read(world);
            if (full.gold() == null) {
                spec.commandLine().getErr().println("robosim goldfinder: world " + world + " has no <gold>");
                return 1;
            }
            w = full.withFirstRobots(robots);
        } catch (WorldFileException | IllegalArgumentException e) {
            spec.commandLine().getErr().println("robosim goldfinder: " + e.getMessage());
            return e instanceof WorldFileException ? 1 : 2;
        }
        Path frames = out.resolve("frames");
        Files.createDirectories(frames);
        Simulation sim = new Simulation(w, seed);
        // the run's own secret: the team and the viewer present it, nobody else can join or watch
        String secret = RunSecret.create();
        ServerOptions options = ServerOptions.loopback().withMaxSteps(maxSteps).withWaitViewers(noFrames ? 0 : 1)
                .withAccess(Access.secret(secret));
        String before = System.getProperty(RunSecret.PROPERTY);
        System.setProperty(RunSecret.PROPERTY, secret);
        try {
            return run(o, w, sim, frames, options, secret);
        } finally {
            if (before == null) {
                System.clearProperty(RunSecret.PROPERTY);
            } else {
                System.setProperty(RunSecret.PROPERTY, before);
            }
        }
    }

    private int run(PrintWriter o, World w, Simulation sim, Path frames, ServerOptions options, String secret)
            throws Exception {
        o.printf(Locale.ROOT, "Seed: %d%nGoldFinder: world %s, %d robots%s, gold at (%.0f, %.0f)%n", seed, w.name(),
                robots, separateJvms ? " in separate JVMs" : " as threads", w.gold().x(), w.gold().y());
        o.flush();
        try (EnvironmentServer server = new EnvironmentServer(sim, options)) {
            server.bind();
            PngImageWriter png = new PngImageWriter(frames);
            CompletableFuture<ViewerSummary> viewer = noFrames ? null : Background.supply("png viewer", () -> {
                try {
                    return Viewers.pngClient("127.0.0.1", server.viewerPort(), png, every, 800, false, true,
                            Duration.ofMinutes(5)).run();
                } catch (java.io.IOException e) {
                    throw new IllegalStateException(e.getMessage(), e);
                }
            });
            List<Process> processes = new ArrayList<>();
            try {
                if (separateJvms) {
                    for (int k = 1; k <= robots; k++) {
                        processes.add(RobotProcesses.start("robosim.examples.goldfinder.Gold", "r" + k,
                                server.robotPort(), secret, out.resolve("r" + k + ".log"),
                                Double.toString(cellSize), Long.toString(seed)));
                    }
                } else {
                    GoldFinder.start("127.0.0.1", server.robotPort(), robots, cellSize, seed);
                }
                RunReport report;
                try (RunProgressLine progress = RunProgressLine.follow(server, spec.commandLine().getErr(), quiet.quiet, true)) {
                    report = server.run();
                }
                summary(o, report, w.stepMs());
                if (viewer != null) {
                    viewer.get(60, TimeUnit.SECONDS);
                    o.printf(Locale.ROOT, "Frames: %d PNG files in %s%n", png.imagesWritten(), frames.toAbsolutePath());
                }
                return report.find() != null ? 0 : NOT_FOUND;
            } finally {
                RobotProcesses.stop(processes);
            }
        }
    }

    static void summary(PrintWriter o, RunReport report, int stepMs) {
        if (report.find() != null) {
            o.printf(Locale.ROOT, "Gold found by %s at step %d (%.1f s simulated)%n", report.find().robot(),
                    report.find().step(), report.find().step() * stepMs / 1000.0);
        } else {
            o.printf(Locale.ROOT, "Gold not found: %s%n", report.endReason());
        }
        for (RobotSummary r : report.robots()) {
            o.printf(Locale.ROOT, "robot %s: travelled %.0f mm, collisions %d, pose (%.0f, %.0f, %.1f), %s%n", r.name(),
                    r.distance(), r.collisions(), r.x(), r.y(), r.th(), EnvCommand.howItEnded(report, r.name()));
        }
        o.flush();
    }
}
