package robosim.cli;

import java.io.File;
import java.io.IOException;
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
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robosim.env.core.Simulation;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.World;
import robosim.env.world.WorldReader;
import robosim.viewer.ViewerSummary;

/**
 * {@code robosim demo}: the Environment on the small maze, two wander robots in two JVMs of their
 * own, and a viewer writing PNG frames.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = "Run the demo: two wander robots (each in its own JVM) in the small maze, frames written as PNG.")
final class DemoCommand implements Callable<Integer> {
    static final String WANDER = "robosim.examples.wander.Wander";

    @Spec
    CommandSpec spec;

    @Option(names = "--out", defaultValue = "out/demo", paramLabel = "DIR", description = "where the frames go; default ${DEFAULT-VALUE}")
    Path out;

    @Option(names = "--steps", defaultValue = "600", paramLabel = "N", description = "steps to run (100 ms each); default ${DEFAULT-VALUE}")
    long steps;

    @Option(names = "--every", defaultValue = "10", paramLabel = "K", description = "write a frame every K steps; default ${DEFAULT-VALUE}")
    int every;

    @Override
    public Integer call() throws Exception {
        PrintWriter o = spec.commandLine().getOut();
        if (steps < 1) {
            spec.commandLine().getErr().println("robosim demo: " + steps + " was supplied for --steps: it must be at least 1");
            return 2;
        }
        Path root = Path.of(System.getProperty("robosim.root", "."));
        World world = WorldReader.read(root.resolve("testLoadFiles/environment/small-maze.xml"));
        Path frames = out.resolve("frames");
        Files.createDirectories(frames);
        Simulation sim = new Simulation(world);
        ServerOptions options = ServerOptions.loopback().withMaxSteps(steps).withWaitViewers(1);
        try (EnvironmentServer server = new EnvironmentServer(sim, options)) {
            server.bind();
            o.printf(Locale.ROOT, "Demo: world %s, %d steps, robots %s%n", world.name(), steps, sim.robotNames());
            o.flush();
            CompletableFuture<ViewerSummary> viewer = CompletableFuture.supplyAsync(() -> {
                try {
                    return Viewers.pngClient("127.0.0.1", server.viewerPort(), frames, every, 800, true, true,
                            Duration.ofMinutes(2)).run();
                } catch (IOException e) {
                    throw new IllegalStateException(e.getMessage(), e);
                }
            });
            List<Process> robots = new ArrayList<>();
            try {
                for (String name : sim.robotNames()) {
                    robots.add(RobotProcesses.start(WANDER, name, server.robotPort(), out.resolve(name + ".log")));
                }
                RunReport report = server.run();
                EnvCommand.printReport(o, report);
                ViewerSummary v = viewer.get(60, TimeUnit.SECONDS);
                o.printf(Locale.ROOT, "Frames: %d PNG files in %s%n", v.framesWritten(), frames.toAbsolutePath());
                o.printf(Locale.ROOT, "Robot logs: %s%n", out.toAbsolutePath() + File.separator + "<robot>.log");
            } finally {
                RobotProcesses.stop(robots);
            }
        }
        return 0;
    }
}
