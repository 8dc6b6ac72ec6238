package robosim.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import robosim.aria.ArRobot;
import robosim.env.core.Parallel;
import robosim.env.core.Simulation;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.hw.EnvironmentLinks;
import robosim.hw.RobotRuntime;
import robosim.hw.RobotThreads;
import robosim.hw.RuntimeChoices;

/**
 * The grid world with the robots in the Environment's JVM, on an in-process link: the same
 * Environment, the same robot programs as {@link BenchRobots} (each robot its own thread,
 * {@code HardwareSimulator}, request queue and lockstep), with the messages handed over as objects
 * instead of frames over TCP. The gap to {@link CoreBench} is what the lockstep's hand-offs cost.
 */
public final class InProcessBench {
    /** How long the robots' threads may take to end once the run is over, ms. */
    private static final long ROBOTS_END_MS = 30_000;

    private InProcessBench() {
    }

    /**
     * Runs one measurement in-process.
     *
     * @param robots    robots in the grid
     * @param sensors   what each robot reads
     * @param steps     steps to run
     * @param dir       where to write the world
     * @param robotFile the p3dx parameter file
     * @param threads   threads of the Environment that read the robots' sensors ({@code --threads})
     * @param window    steps per window of this JVM's step rate, CPU time and allocation; 0 for none
     * @return the figures; {@code clients} is 0, the memory and windows are this JVM's, robots included
     * @throws IOException           if the world cannot be written or the ports bound
     * @throws InterruptedException  if interrupted
     * @throws IllegalStateException if a robot fails or the run ends early
     */
    public static StepRateBench.Result run(int robots, BenchSensors sensors, long steps, Path dir, Path robotFile,
                                           int threads, long window) throws IOException, InterruptedException {
        Path worldFile = GridWorld.write(robots, dir, robotFile);
        StepRateBench.Loaded loaded = StepRateBench.load(worldFile, Parallel.SERIAL);
        Simulation sim = loaded.sim();
        ServerOptions options = StepRateBench.serverOptions(steps, threads);
        StepWindows windows = window > 0 ? new StepWindows(window) : null;
        // a runtime of the bench's own: whatever links the system properties choose, it takes the in-process one
        RobotRuntime runtime = RobotRuntime.create("bench", RuntimeChoices.fromSystemProperties()
                .withLinks(EnvironmentLinks.Mode.AUTO));
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread runner = Thread.currentThread();
        List<Thread> threadsStarted = new ArrayList<>();
        RunReport report;
        try (EnvironmentServer server = new EnvironmentServer(sim, options)) {
            server.bind();
            server.admitInProcess();
            String params = robotFile.toAbsolutePath().toString();
            for (int k = 0; k < robots; k++) {
                ArRobot robot = new ArRobot("b" + k, "127.0.0.1", server.robotPort(), params);
                robot.setRuntime(runtime);
                Thread t = RobotThreads.unstarted(robot.getName(), () -> BenchRobots.drive(robot, sensors, null, null, () -> { }));
                t.setUncaughtExceptionHandler((thread, e) -> {
                    if (failure.compareAndSet(null, e)) {
                        runner.interrupt();
                    }
                });
                threadsStarted.add(t);
                t.start();
            }
            Thread sampler = windows == null ? null : StepRateBench.sampler(sim, null, windows);
            try {
                report = server.run();
            } catch (InterruptedException e) {
                Throwable failed = failure.get();
                if (failed != null) {
                    throw new IllegalStateException("a robot failed: " + failed, failed);
                }
                throw e;
            } finally {
                if (sampler != null) {
                    sampler.interrupt();
                    sampler.join();
                }
            }
            if (report.steps() != steps) {
                throw new IllegalStateException("the run ended early: " + report.endReason());
            }
            if (server.inProcessLinks() != 1) {
                throw new IllegalStateException("the robots opened " + server.inProcessLinks()
                        + " in-process links, not one: they did not all run in-process");
            }
            if (windows != null) {
                windows.end(report.steps());
            }
        }
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ROBOTS_END_MS);
        for (Thread t : threadsStarted) {
            t.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
        }
        List<JvmMemory.Report> memory = List.of(new JvmMemory.Report("env", JvmMemory.figures(null)));
        List<StepRateBench.WindowReport> windowReports = windows == null ? List.of()
                : List.of(new StepRateBench.WindowReport("env", windows.windows()));
        return new StepRateBench.Result("in-process", robots, sensors, 0,
                loaded.load(report.connectedNanoTime() - loaded.builtAt()), report.steps(), report.wallNanos() / 1e9,
                memory, windowReports);
    }
}
