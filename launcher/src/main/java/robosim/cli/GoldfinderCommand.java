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
import java.util.concurrent.TimeoutException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
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
import robosim.env.world.maze.MazeWorldWriter;
import robosim.protocol.RunSecret;
import robosim.env.world.xml.WorldFileException;
import robosim.env.world.xml.WorldReader;
import robosim.examples.goldfinder.GoldFinder;
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

    @Option(names = "--robots", defaultValue = "3", paramLabel = "N", description = OptionTexts.ROBOTS
            + "; the team: the world's first N robots; default ${DEFAULT-VALUE}")
    int robots;

    @Option(names = "--separate-jvms", description = "run each robot in a JVM of its own")
    boolean separateJvms;

    @Option(names = "--seed", defaultValue = "1", paramLabel = "SEED", description = OptionTexts.SEED
            + "; the run's and the team's tie-breaks; default ${DEFAULT-VALUE}")
    long seed;

    @Option(names = "--out-dir", defaultValue = "out/goldfinder", paramLabel = "DIR", description = OptionTexts.OUT_DIR
            + "; frames in DIR/frames, each robot's log in DIR/rN.log; default ${DEFAULT-VALUE}")
    Path out;

    @Option(names = "--out", hidden = true, paramLabel = "DIR", description = OptionTexts.OLD_NAME + "--out-dir")
    Path oldOut;

    @Option(names = "--steps", defaultValue = "20000", paramLabel = "N", description = OptionTexts.STEPS
            + "; the search stops there if the gold is not found; default ${DEFAULT-VALUE}")
    long maxSteps;

    @Option(names = "--max-steps", hidden = true, paramLabel = "N", description = OptionTexts.OLD_NAME + "--steps")
    Long oldMaxSteps;

    @Option(names = "--every", defaultValue = OptionTexts.EVERY_DEFAULT, paramLabel = "K", description = OptionTexts.EVERY)
    int every;


    @Option(names = "--no-frames", description = "write no PNG frames")
    boolean noFrames;

    @Option(names = "--drawings", description = OptionTexts.DRAWINGS + "; in the frames and the GIF")
    boolean drawings;

    @Mixin
    RecordOptions recording = new RecordOptions();

    @Option(names = "--gif", paramLabel = "FILE",
            description = "write an animated GIF that loops; of the frames, played at " + GIF_SPEED + "x simulated time")
    Path gif;

    /** How long the viewer may take, after the run, to write the frames it has not written yet, s. */
    static final int VIEWER_WAIT_S = 300;

    /** How much faster than simulated time the GIF plays: the demo's search fits in half a minute. */
    static final int GIF_SPEED = 20;

    @Mixin
    QuietOption quiet = new QuietOption();

    @Override
    public Integer call() throws Exception {
        out = oldOut != null ? oldOut : out;
        maxSteps = oldMaxSteps != null ? oldMaxSteps : maxSteps;
        try {
            // checked before the run: a value the viewer or the server would refuse mid-run costs a wait
            ServerOptions.requireAtLeast("--steps", maxSteps, 0);
            ServerOptions.requireAtLeast("--robots", robots, 1);
            ServerOptions.requireAtLeast("--every", every, 1);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        PrintWriter o = spec.commandLine().getOut();
        World w;
        try {
            World full = WorldReader.read(world);
            if (full.gold() == null) {
                spec.commandLine().getErr().println("robosim goldfinder: world " + world + " has no <gold>");
                return 1;
            }
            if (!full.properties().containsKey(MazeWorldWriter.CELL_SIZE_PROPERTY)) {
                spec.commandLine().getErr().println("robosim goldfinder: world " + world + " has no <property name=\""
                        + MazeWorldWriter.CELL_SIZE_PROPERTY + "\" value=\"MM\"/>: the Gold robots read the maze's cell size"
                        + " from it (robosim maze writes it)");
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
        ServerOptions options = ServerOptions.loopback().withMaxSteps(maxSteps).withWaitViewers(watched() ? 1 : 0)
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
        try (EnvironmentServer server = new EnvironmentServer(sim, options);
             RunOutputs outputs = RunOutputs.open(spec.commandLine().getErr(), "goldfinder", noFrames ? null : frames,
                     gif, Math.max(1, Math.round(w.stepMs() * (double) every / GIF_SPEED)), recording)) {
            if (outputs == null) {
                return 1;
            }
            server.bind();
            CompletableFuture<ViewerSummary> viewer = !watched() ? null : Background.supply("png viewer", () -> {
                try {
                    return Viewers.client("127.0.0.1", server.viewerPort(), "png:" + frames.getFileName(),
                            outputs.listeners(every, 800, drawings), Duration.ofMinutes(5)).run();
                } catch (java.io.IOException e) {
                    throw new IllegalStateException(e.getMessage(), e);
                }
            });
            List<Process> processes = new ArrayList<>();
            try {
                if (separateJvms) {
                    for (int k = 1; k <= robots; k++) {
                        processes.add(RobotProcesses.start("robosim.examples.goldfinder.Gold", "r" + k,
                                server.robotPort(), secret, out.resolve("r" + k + ".log")));
                    }
                } else {
                    GoldFinder.start("127.0.0.1", server.robotPort(), robots);
                }
                RunReport report;
                try (RunProgressLine progress = RunProgressLine.follow(server, spec.commandLine().getErr(), quiet.quiet, true)) {
                    report = server.run();
                }
                summary(o, report, w.stepMs());
                if (viewer != null) {
                    try {
                        viewer.get(VIEWER_WAIT_S, TimeUnit.SECONDS);
                    } catch (TimeoutException e) {
                        spec.commandLine().getErr().println("robosim goldfinder: the viewer had not written its frames "
                                + VIEWER_WAIT_S + " s after the run ended; the files may be incomplete");
                        return 1;
                    }
                }
                int written = outputs.report(o, spec.commandLine().getErr(), "goldfinder");
                if (written != 0) {
                    return written;
                }
                return report.find() != null ? 0 : NOT_FOUND;
            } finally {
                RobotProcesses.stop(processes);
            }
        }
    }

    /** @return whether a viewer attaches: for the PNG frames, the recording or the GIF */
    private boolean watched() {
        return !noFrames || recording.requested() || gif != null;
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
