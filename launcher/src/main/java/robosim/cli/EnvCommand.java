package robosim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.function.Function;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robosim.env.core.RobotSummary;
import robosim.env.core.Simulation;
import robosim.env.net.Departure;
import robosim.env.net.Join;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.RobotToPlace;
import robosim.env.world.World;
import robosim.pioneer.server.PioneerPorts;
import robosim.env.world.xml.WorldFileException;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.FrameReader;
import robosim.protocol.recording.RecordingWriter;

/** {@code robosim env}: loads a world, waits for its robots, runs the lockstep steps. */
@Command(name = "env", mixinStandardHelpOptions = true,
        description = "Run the Environment: load WORLD, wait for the robots it names, run, print each robot's end"
                + " (ran to the end, or left, dropped or lost, with the step and the reason).")
final class EnvCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "WORLD", description = "the world file (XML), or an ARIA map (.map)")
    Path world;

    @Option(names = "--robot", paramLabel = "TYPE[:NAME]", description = "add a robot at the world's next home"
            + " (a map's RobotHome cairns); TYPE is a shipped parameter file (p3dx, p3at, scout) or a path;"
            + " NAME defaults to TYPE_1, TYPE_2, ...; repeatable; a map without any gets one p3dx")
    List<String> robots = List.of();

    @Option(names = "--robot-port", defaultValue = "5000", paramLabel = "PORT", description = OptionTexts.ROBOT_PORT
            + "; where robots connect (0: any free port); default ${DEFAULT-VALUE}")
    int port;

    @Option(names = "--port", hidden = true, paramLabel = "PORT", description = OptionTexts.OLD_NAME + "--robot-port")
    Integer oldPort;

    @Option(names = "--viewer-port", defaultValue = "3000", paramLabel = "PORT", description = OptionTexts.VIEWER_PORT
            + "; where viewers connect (0: any free port); default ${DEFAULT-VALUE}")
    int viewerPort;

    @Option(names = "--bind", defaultValue = "127.0.0.1", paramLabel = "ADDRESS", description = "address to listen on; default ${DEFAULT-VALUE}")
    String bind;

    @Option(names = "--seed", defaultValue = "1", paramLabel = "SEED", description = OptionTexts.SEED
            + "; the same world, seed and robots give the same run; default ${DEFAULT-VALUE}")
    long seed;

    @Option(names = "--steps", defaultValue = "0", paramLabel = "N", description = OptionTexts.STEPS
            + "; 0 runs until every robot has disconnected; default ${DEFAULT-VALUE}")
    long steps;

    @Option(names = "--realtime", description = "pace steps at the world's step length instead of as fast as possible")
    boolean realtime;

    @Option(names = "--step-timeout", defaultValue = "10000", paramLabel = "MS", description = "ms to wait for a robot's requests before dropping it; default ${DEFAULT-VALUE}")
    long stepTimeoutMs;

    @Option(names = "--first-steps-timeout", defaultValue = "60000", paramLabel = "MS", description = "ms to wait for a"
            + " robot's requests in each of its first 3 steps (it loads its classes then), if longer than"
            + " --step-timeout; default ${DEFAULT-VALUE}")
    long firstStepsTimeoutMs;

    @Option(names = "--connect-timeout", defaultValue = "600", paramLabel = "S", description = "seconds to wait for the world's robots; default ${DEFAULT-VALUE}")
    long connectTimeoutS;

    @Mixin
    RecordOptions recording;

    @Mixin
    AccessOptions access;

    @Mixin
    PioneerOptions pioneer;

    @Option(names = "--open", description = "admit robots the world does not name, at its <spawn> poses, as the"
            + " world's open=\"true\" does (docs/WORLD-FORMAT.md)")
    boolean open;

    @Option(names = "--wait-viewers", defaultValue = "0", paramLabel = "N", description = "viewers to wait for before the first step; default ${DEFAULT-VALUE}")
    int waitViewers;

    @Mixin
    QuietOption quiet;

    @Option(names = "--in-process", paramLabel = "[ROBOT=]CLASS", description = "run a robot program in this JVM,"
            + " reaching the Environment without TCP (the same run as over TCP, faster): CLASS for every robot of"
            + " the world not given one by name, ROBOT=CLASS for one robot; repeatable")
    List<String> inProcess = new ArrayList<>();

    @Option(names = {"--classpath", "--cp"}, paramLabel = "PATH",
            description = OptionTexts.CLASSPATH + "; for the --in-process programs")
    String classpath;

    @Option(names = "--threads", paramLabel = "N", description = OptionTexts.THREADS + "; "
            + "1 reads them on the step loop's thread; the run is the same with any number; default: the processors available")
    Integer threads;

    /**
     * @return the robots asked for with {@code --robot}, in order
     * @throws ParameterException if one is not {@code TYPE} or {@code TYPE:NAME}
     */
    List<RobotToPlace> robotsToPlace() {
        try {
            return robots.stream().map(RobotToPlace::parse).toList();
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
    }

    @Override
    public Integer call() throws Exception {
        // the server's classes are read now, while files can still be opened (see ClassPreload)
        ClassPreload.load(List.of("robosim."), EnvironmentServer.class, robosim.protocol.Message.class,
                robosim.pioneer.server.PioneerPorts.class, robosim.pioneer.PioneerPacket.class,
                robosim.comms.CommsSettings.class, robosim.geometry.GeometryClient.class, EnvCommand.class);
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        World w;
        List<RobotToPlace> toPlace = robotsToPlace();
        try {
            w = WorldReader.read(world, toPlace);
            if (open) {
                w = w.withRules(w.rules().withOpen(true));
            }
        } catch (WorldFileException e) {
            err.println("robosim env: " + e.getMessage());
            return 1;
        }
        ServerOptions options;
        port = oldPort != null ? oldPort : port;
        try {
            checkFlags();
            options = new ServerOptions(bind, port, viewerPort, steps, realtime, stepTimeoutMs,
                    connectTimeoutS * 1000, waitViewers, FrameReader.DEFAULT_MAX_FRAME, threads(), access.limits(),
                    access.access(), firstStepsTimeoutMs);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        InProcessPrograms programs = null;
        if (!inProcess.isEmpty()) {
            try {
                programs = InProcessPrograms.of(inProcess, w.robots().stream().map(r -> r.name()).toList(),
                        ProgramClasspath.loader(classpath));
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage());
            }
        }
        Simulation sim = new Simulation(w, seed);
        EnvironmentServer made;
        try {
            made = new EnvironmentServer(sim, options);
        } catch (IllegalArgumentException e) {
            err.println("robosim env: " + e.getMessage());
            return 1;
        }
        List<Path> secretFiles = List.of();
        String secret = options.access().secret();
        PioneerPorts pioneerPorts = null;
        try (EnvironmentServer server = made) {
            try {
                // the secret is where clients look before anyone can connect (see publishAhead)
                secretFiles = secret == null ? List.of() : access.publishAhead(secret, bind, port, viewerPort);
            } catch (IOException e) {
                err.println("robosim env: cannot write the run secret: " + e.getMessage());
                return 1;
            }
            try {
                server.bind();
            } catch (IllegalStateException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage() + " (leave out --no-token)");
            } catch (IOException e) {
                err.println("robosim env: " + e.getMessage() + " (--robot-port and --viewer-port choose others;"
                        + " 0 takes any free port)");
                return 1;
            }
            if (secret != null) {
                try {
                    secretFiles = access.publish(secret, out, server.robotPort(), server.viewerPort());
                    List<Path> written = secretFiles;
                    // an env stopped by Ctrl-C or kill removes them too
                    Runtime.getRuntime().addShutdownHook(new Thread(() -> AccessOptions.unpublish(written, secret),
                            "remove-run-secret"));
                } catch (IOException e) {
                    err.println("robosim env: cannot write the run secret: " + e.getMessage());
                    return 1;
                }
            } else {
                out.println("Run secret: none (--no-token): anyone on this machine may join, watch and change the run");
            }
            if (pioneer.requested()) {
                try {
                    pioneerPorts = pioneer.open(w, bind, server.robotPort(), secret, realtime, out);
                } catch (IOException | IllegalArgumentException e) {
                    err.println("robosim env: " + e.getMessage() + " (--pioneer-port chooses others; 0 takes free ports)");
                    return 1;
                }
            }
            RecordingWriter recorder = null;
            if (recording.requested()) {
                recorder = recording.create(err, "env");
                if (recorder == null) {
                    return 1;
                }
                server.addSnapshotListener(recorder);
            }
            out.printf(Locale.ROOT, "Seed: %d%n", seed);
            out.printf(Locale.ROOT, "Environment: world %s, robots on %s:%d, viewers on %s:%d%n", w.name(), bind,
                    server.robotPort(), bind, server.viewerPort());
            if (w.rules().open()) {
                // an open world starts at its first robot, named or not
                out.printf(Locale.ROOT, "Open world: robots it does not name join at its %d spawn pose(s); the run starts"
                        + " at the first robot%s%n", w.rules().spawns().size(), sim.robotNames().isEmpty() ? ""
                        : " (it names " + String.join(", ", sim.robotNames()) + ")");
            } else {
                out.printf(Locale.ROOT, "Waiting for robots: %s%n", String.join(", ", sim.robotNames()));
            }
            if (programs != null) {
                server.admitInProcess();
                out.printf(Locale.ROOT, "In-process: %s%n", String.join(", ", programs.robots()));
                programs.start(server.robotPort(), err);
            }
            out.flush();
            RunReport report;
            // the progress line is closed (a terminal's line cleared) before the error or the report
            try (RunProgressLine progress = RunProgressLine.follow(server, err, quiet.quiet, false)) {
                report = server.run();
            } catch (IllegalStateException e) {
                err.println("robosim env: " + e.getMessage());
                return 1;
            }
            printReport(out, report, pioneerPorts == null ? robot -> Optional.empty() : pioneerPorts::unattended);
            if (programs != null && !programs.finish()) {
                return 1;
            }
            if (recorder != null) {
                return recording.report(out, err, "env", recorder);
            }
        } finally {
            if (pioneerPorts != null) {
                pioneerPorts.close();
            }
            AccessOptions.unpublish(secretFiles, secret);
        }
        return 0;
    }

    /** Names the flag the user typed, with the value and the server's rule, before the server checks them. */
    private void checkFlags() {
        ServerOptions.requirePort(oldPort != null ? "--port" : "--robot-port", port);
        ServerOptions.requirePort("--viewer-port", viewerPort);
        ServerOptions.requireAtLeast("--steps", steps, 0);
        ServerOptions.requireAtLeast("--step-timeout", stepTimeoutMs, 1);
        ServerOptions.requireAtLeast("--first-steps-timeout", firstStepsTimeoutMs, 1);
        ServerOptions.requireAtLeast("--connect-timeout", connectTimeoutS, 1);
        ServerOptions.requireAtLeast("--wait-viewers", waitViewers, 0);
        ServerOptions.requireAtLeast("--threads", threads(), 1);
        pioneer.check();
    }

    private int threads() {
        return threads == null ? ServerOptions.defaultThreads() : threads;
    }

    static void printReport(PrintWriter out, RunReport report) {
        printReport(out, report, robot -> Optional.empty());
    }

    /**
     * @param unattended what the Pioneer ports say of a robot the run had to the end but whose ARIA
     *                   client left before it (see {@link PioneerPorts#unattended(String)})
     */
    static void printReport(PrintWriter out, RunReport report, Function<String, Optional<String>> unattended) {
        out.printf(Locale.ROOT, "Run ended after %d steps (%.1f s simulated): %s%n", report.steps(),
                report.timeMs() / 1000.0, report.endReason());
        if (report.find() != null) {
            out.printf(Locale.ROOT, "Gold found by %s at step %d%n", report.find().robot(), report.find().step());
        }
        if (!report.joins().isEmpty()) {
            out.printf(Locale.ROOT, "Robots joined during the run: %d, went: %d%n", report.joins().size(),
                    report.departures().size());
        }
        for (RobotSummary r : report.robots()) {
            out.printf(Locale.ROOT, "robot %s: pose (%.0f, %.0f, %.1f) travelled %.0f mm, collisions %d, %s%s%n",
                    r.name(), r.x(), r.y(), r.th(), r.distance(), r.collisions(), howItEnded(report, r.name(), unattended),
                    howItJoined(report, r.name()));
        }
        out.flush();
    }

    /**
     * @return {@code ran to the end}, {@code never connected to this run}, or how the robot went
     *         before the end: {@code left}, {@code dropped}
     *         or {@code lost}, the step and the reason
     */
    static String howItEnded(RunReport report, String robot) {
        return howItEnded(report, robot, r -> Optional.empty());
    }

    /**
     * @return as {@link #howItEnded(RunReport, String)}, but for a robot the run had to the end whose
     *         ARIA client left before, what its Pioneer port says instead of {@code ran to the end}
     */
    static String howItEnded(RunReport report, String robot, Function<String, Optional<String>> unattended) {
        if (report.absent().contains(robot)) {
            return "never connected to this run";
        }
        return report.departure(robot).map(Departure::describe)
                .or(() -> unattended.apply(robot)).orElse("ran to the end");
    }

    /** @return {@code ""} for a robot there from the start, else how it last joined, such as {@code " (rejoined at step 12)"} */
    static String howItJoined(RunReport report, String robot) {
        List<Join> joins = report.joinsOf(robot);
        return joins.isEmpty() ? "" : " (" + joins.get(joins.size() - 1).describe() + ")";
    }
}
