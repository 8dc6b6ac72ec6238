package robosim.bench;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import robosim.env.core.Parallel;
import robosim.env.core.Simulation;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunReport;
import robosim.env.net.Access;
import robosim.env.net.Limits;
import robosim.env.net.ServerOptions;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.FrameReader;

/**
 * Steps per second, as fast as possible, in the grid world: the Environment in this JVM, the robots
 * in client JVMs of their own (robots spread evenly over them), over TCP on loopback. Also times
 * loading: reading the world file, building the {@link Simulation}, and starting the clients until
 * every robot has connected.
 */
public final class StepRateBench {
    /** How long the Environment waits for every robot to connect, ms. */
    static final long CONNECT_TIMEOUT_MS = 180_000;
    /** How long the Environment waits for a robot's requests, ms: long, so a slow step drops no one. */
    static final long STEP_TIMEOUT_MS = 60_000;
    /** How long the client JVMs get to end by themselves after the run, ms. */
    private static final long CLIENT_EXIT_MS = 30_000;
    /** How often the Environment's heap sampler looks at the step count, ms. */
    private static final long SAMPLER_POLL_MS = 2;

    /**
     * Where the load-and-connect time went.
     *
     * @param readNanos    reading the world file
     * @param buildNanos   building the {@link Simulation}
     * @param connectNanos from starting the client JVMs until every robot had connected (0 for the
     *                     core alone)
     */
    public record Load(long readNanos, long buildNanos, long connectNanos) {
        /** @return the whole load-and-connect time, seconds */
        public double seconds() {
            return (readNanos + buildNanos + connectNanos) / 1e9;
        }
    }

    /**
     * A world read and its simulation built, timed.
     *
     * @param sim        the simulation
     * @param readNanos  reading the world file
     * @param buildNanos building the simulation
     * @param builtAt    {@link System#nanoTime()} once it was built
     */
    record Loaded(Simulation sim, long readNanos, long buildNanos, long builtAt) {
        /** @return where the time went, with the given time to connect */
        Load load(long connectNanos) {
            return new Load(readNanos, buildNanos, connectNanos);
        }
    }

    /** Reads a world and builds its simulation, timing each. */
    static Loaded load(Path worldFile, Parallel parallel) {
        long t0 = System.nanoTime();
        World world = WorldReader.read(worldFile);
        long t1 = System.nanoTime();
        Simulation sim = new Simulation(world, 1, parallel);
        long t2 = System.nanoTime();
        return new Loaded(sim, t1 - t0, t2 - t1, t2);
    }

    /**
     * One measurement.
     *
     * @param run     {@code tcp} (robots in client JVMs) or {@code core} (the core alone, one thread)
     * @param robots  robots in the grid
     * @param sensors what each robot reads
     * @param clients client JVMs (0 for the core alone)
     * @param load    the load-and-connect time
     * @param steps   steps run
     * @param seconds wall-clock time of the steps
     * @param memory  each JVM's memory at the end of the run over TCP: the Environment's (this JVM)
     *                first, then each client's; empty for the core alone
     * @param windows with {@code --window}, each JVM's windows of the run (this JVM's first, then each
     *                client's); empty without
     */
    public record Result(String run, int robots, BenchSensors sensors, int clients, Load load, long steps,
                         double seconds, List<JvmMemory.Report> memory, List<WindowReport> windows) {
        /** Copies the memory figures and the windows. */
        public Result {
            memory = List.copyOf(memory);
            windows = List.copyOf(windows);
        }

        /**
         * A result without memory figures nor windows.
         *
         * @param run     {@code tcp} or {@code core}
         * @param robots  robots in the grid
         * @param sensors what each robot reads
         * @param clients client JVMs (0 for the core alone)
         * @param load    the load-and-connect time
         * @param steps   steps run
         * @param seconds wall-clock time of the steps
         */
        public Result(String run, int robots, BenchSensors sensors, int clients, Load load, long steps, double seconds) {
            this(run, robots, sensors, clients, load, steps, seconds, List.of(), List.of());
        }

        /** @return this result with the given windows */
        Result withWindows(List<WindowReport> windows) {
            return new Result(run, robots, sensors, clients, load, steps, seconds, memory, windows);
        }

        /** @return steps per second */
        public double stepsPerSecond() {
            return steps / seconds;
        }

        /** @return how many times faster than real time, with 100 ms steps */
        public double realtimeFactor() {
            return stepsPerSecond() * 0.1;
        }

        /** @return robots × steps per second */
        public double robotStepsPerSecond() {
            return robots * stepsPerSecond();
        }
    }

    /**
     * One JVM's windows of a run ({@code --window}).
     *
     * @param jvm     {@code env} (this JVM) or {@code client0}, {@code client1}...
     * @param windows its windows, in order; empty if a client did not report them
     */
    public record WindowReport(String jvm, List<StepWindows.Window> windows) {
        /** Copies the windows. */
        public WindowReport {
            windows = List.copyOf(windows);
        }
    }

    private StepRateBench() {
    }

    /**
     * Runs one measurement over TCP. The client JVMs are stopped before this returns, also when it
     * fails: each gets a bounded time to end by itself, then is ended. Once the steps are over, each
     * JVM's memory is taken ({@link JvmMemory#figures}): this JVM's (the Environment's) while it still
     * holds the simulation, each client's while it still holds its disconnected robots, which it
     * prints in its log for this to read.
     *
     * @param robots    robots in the grid
     * @param sensors   what each robot reads
     * @param clients   client JVMs to spread the robots over (fewer if there are fewer robots)
     * @param steps     steps to run
     * @param dir       where to write the world and the clients' logs
     * @param robotFile the p3dx parameter file
     * @param threads   threads of the Environment that read the robots' sensors ({@code --threads})
     * @param heapEvery steps between samples of each JVM's heap after its last garbage collection
     *                  ({@link JvmMemory.Sampler}, forcing none); 0 for none
     * @param window    steps per window of each JVM's step rate, CPU time and allocation
     *                  ({@link StepWindows}, from the first step on); 0 for none
     * @return the figures
     * @throws IOException           if the world or a client JVM cannot be started
     * @throws InterruptedException  if interrupted
     * @throws IllegalStateException if a client JVM fails or the run ends early
     */
    public static Result run(int robots, BenchSensors sensors, int clients, long steps, Path dir, Path robotFile,
                             int threads, long heapEvery, long window) throws IOException, InterruptedException {
        Path worldFile = GridWorld.write(robots, dir, robotFile);
        // the server hands the simulation its sensing threads
        Loaded loaded = load(worldFile, Parallel.SERIAL);
        Simulation sim = loaded.sim();
        ServerOptions options = serverOptions(steps, threads);
        List<BenchRobots.Share> shares = BenchRobots.split(robots, clients);
        List<Process> started = new CopyOnWriteArrayList<>();
        ClientWatch watch = new ClientWatch(Thread.currentThread());
        Thread stopOnExit = new Thread(() -> started.forEach(Process::destroyForcibly), "bench-stop-clients");
        Runtime.getRuntime().addShutdownHook(stopOnExit);
        JvmMemory.Sampler samples = heapEvery > 0 ? new JvmMemory.Sampler(heapEvery) : null;
        StepWindows windows = window > 0 ? new StepWindows(window) : null;
        List<JvmMemory.Report> memory = new ArrayList<>();
        Result result;
        try (EnvironmentServer server = new EnvironmentServer(sim, options)) {
            server.bind();
            for (int c = 0; c < shares.size(); c++) {
                Process p = clientJvm(server.robotPort(), shares.get(c), sensors, robotFile, log(dir, robots, sensors, c),
                        heapEvery, window);
                started.add(p);
                watch.watch(p, log(dir, robots, sensors, c));
            }
            RunReport report;
            Thread sampler = samples == null && windows == null ? null : sampler(sim, samples, windows);
            try {
                report = server.run();
            } catch (InterruptedException e) {
                String failure = watch.failure();
                if (failure != null) {
                    throw new IllegalStateException(failure);
                }
                throw e;
            } finally {
                watch.stop();
                if (sampler != null) {
                    sampler.interrupt();
                    sampler.join();
                }
            }
            if (report.steps() != steps) {
                throw new IllegalStateException("the run ended early: " + report.endReason() + " (see " + dir + "/client-*.log)");
            }
            if (samples != null) {
                samples.add(report.steps());
            }
            if (windows != null) {
                windows.end(report.steps());
            }
            memory.add(new JvmMemory.Report("env", JvmMemory.figures(samples)));
            Load load = loaded.load(report.connectedNanoTime() - loaded.builtAt());
            result = new Result("tcp", robots, sensors, shares.size(), load, report.steps(), report.wallNanos() / 1e9);
        } finally {
            stop(started);
            try {
                Runtime.getRuntime().removeShutdownHook(stopOnExit);
            } catch (IllegalStateException shuttingDown) {
                // the hook runs anyway
            }
        }
        List<WindowReport> windowReports = new ArrayList<>();
        if (windows != null) {
            windowReports.add(new WindowReport("env", windows.windows()));
        }
        for (int c = 0; c < shares.size(); c++) {
            List<String> lines = logLines(log(dir, robots, sensors, c));
            memory.add(new JvmMemory.Report("client" + c,
                    JvmMemory.clientFigures(lines).orElse(Map.of("figures", JvmMemory.UNAVAILABLE))));
            if (windows != null) {
                windowReports.add(new WindowReport("client" + c, StepWindows.clientWindows(lines).orElse(List.of())));
            }
        }
        return new Result(result.run(), result.robots(), result.sensors(), result.clients(), result.load(), result.steps(),
                result.seconds(), memory, windowReports);
    }

    /**
     * @param steps   steps to run, 0 until stopped
     * @param threads threads that read the robots' sensors
     * @return how the bench's Environment runs: on loopback, any free ports, as fast as it can, no secret
     */
    static ServerOptions serverOptions(long steps, int threads) {
        return new ServerOptions("127.0.0.1", 0, 0, steps, false, STEP_TIMEOUT_MS, CONNECT_TIMEOUT_MS, 0,
                FrameReader.DEFAULT_MAX_FRAME, threads, Limits.defaults(), Access.open());
    }

    /**
     * Starts a thread that samples this JVM's heap and marks its windows each time the simulation's
     * step count reaches the next multiple of their interval, looking every {@value #SAMPLER_POLL_MS}
     * ms; it ends when interrupted. (It reads the step count unsynchronised: a sample may come a step
     * or a poll late, and says at which step it was taken.) The windows start at the first step, so
     * connecting is not in them.
     *
     * @param samples the heap's sampler, or {@code null}
     * @param windows the windows, or {@code null}
     */
    static Thread sampler(Simulation sim, JvmMemory.Sampler samples, StepWindows windows) {
        Thread t = new Thread(() -> {
            try {
                while (!Thread.currentThread().isInterrupted()) {
                    long step = sim.stepCount();
                    if (samples != null) {
                        samples.at(step);
                    }
                    if (windows != null && step > 0) {
                        windows.at(step);
                    }
                    Thread.sleep(SAMPLER_POLL_MS);
                }
            } catch (InterruptedException e) {
                // the run is over
            }
        }, "bench-heap-sampler");
        t.setDaemon(true);
        t.start();
        return t;
    }

    /** @return a client JVM's log, or no lines if it cannot be read */
    private static List<String> logLines(Path log) {
        try {
            return Files.readAllLines(log);
        } catch (IOException e) {
            return List.of();
        }
    }

    private static Path log(Path dir, int robots, BenchSensors sensors, int client) {
        return dir.resolve("client-" + robots + "-" + sensors.optionName() + "-" + client + ".log");
    }

    /**
     * Interrupts the thread running the Environment when a client JVM ends with a failure before the
     * run is over, so a failed client ends the measurement at once instead of at a timeout.
     */
    private static final class ClientWatch {
        private final Thread runner;
        private boolean stopped;
        private String failure;

        ClientWatch(Thread runner) {
            this.runner = runner;
        }

        void watch(Process p, Path log) {
            p.onExit().thenAccept(q -> {
                synchronized (this) {
                    if (!stopped && q.exitValue() != 0 && failure == null) {
                        failure = "a client JVM ended with exit status " + q.exitValue() + " (see " + log + ")";
                        runner.interrupt();
                    }
                }
            });
        }

        synchronized String failure() {
            return failure;
        }

        /** No more interrupts; clears one that was made for a failure. */
        void stop() {
            synchronized (this) {
                stopped = true;
                if (failure != null) {
                    Thread.interrupted();
                }
            }
        }
    }

    /** Gives the clients a bounded time to end by themselves, then ends them. */
    static void stop(List<Process> clients) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(CLIENT_EXIT_MS);
        for (Process p : clients) {
            p.waitFor(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
        }
        for (Process p : clients) {
            if (p.isAlive()) {
                p.destroy();
            }
        }
        for (Process p : clients) {
            if (!p.waitFor(5, TimeUnit.SECONDS)) {
                p.destroyForcibly().waitFor(5, TimeUnit.SECONDS);
            }
        }
    }

    /** The system property whose whitespace-separated words go to every client JVM's command line as options. */
    public static final String CLIENT_JVM_ARGS = "robosim.bench.clientJvmArgs";

    static Process clientJvm(int port, BenchRobots.Share share, BenchSensors sensors, Path robotFile, Path log,
                                     long heapEvery, long window) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-Xss256k", "-Xmx" + clientHeapMb(share.count()) + "m",
                "-cp", System.getProperty("java.class.path")));
        // the clients choose their robots' threads and links as this JVM was told to
        for (String property : List.of("robosim.threads", "robosim.link")) {
            String value = System.getProperty(property);
            if (value != null) {
                cmd.add(cmd.size() - 2, "-D" + property + "=" + value);
            }
        }
        // extra options for the clients alone, e.g. a flight recording of each: -Drobosim.bench.clientJvmArgs="..."
        String extra = System.getProperty(CLIENT_JVM_ARGS, "").trim();
        if (!extra.isEmpty()) {
            cmd.addAll(cmd.size() - 2, List.of(extra.split("\\s+")));
        }
        cmd.addAll(List.of(BenchRobots.class.getName(), "127.0.0.1", Integer.toString(port), Integer.toString(share.first()),
                Integer.toString(share.count()), robotFile.toAbsolutePath().toString(), sensors.optionName(),
                Long.toString(heapEvery), Long.toString(window)));
        return new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
    }

    /**
     * @param robots robots in one client JVM
     * @return its maximum heap, MiB
     */
    static int clientHeapMb(int robots) {
        return 256 + robots;
    }

    /**
     * Prints what the figures mean, once before them.
     *
     * @param out where
     */
    public static void printLegend(PrintWriter out) {
        out.println("step rate: one line per run; load_s = reading the world + building the Simulation (read_s, build_s)"
                + " + starting the client JVMs until every robot has connected (connect_s, 0 for the core alone);"
                + " x_realtime with 100 ms steps; robot_steps_per_s = robots x steps / s");
        out.println("memory: after each run over TCP one mem line per JVM (env = this JVM, which holds the Environment"
                + " and, unless --skip-core, ran the core-alone runs before; clientN = a robots' JVM), MiB: rss_mb, hwm_mb"
                + " = resident set now and at its largest (/proc/self/status VmRSS, VmHWM); heap_gc_mb = heap used after"
                + " the last GC (none forced); heap_committed_mb; gcs = GCs so far; heap_live_mb = heap used after a"
                + " System.gc() then, the simulation or the disconnected robots still held; heap_samples ="
                + " step:heap_gc_mb every --heap-every steps");
        out.println("windows (--window N): after each run one win line per JVM and N steps, from the first step on:"
                + " steps = the steps it covers, steps_per_s (wall clock), cpu_us_per_step = the JVM's CPU time (all its"
                + " threads) per step, alloc_kb_per_step = heap its live platform threads allocated per step (KiB); in the core"
                + " alone, stalled = robots stalled at the window's end");
        out.flush();
    }

    /**
     * Prints a result as one line of {@code key=value} fields.
     *
     * @param out where
     * @param r   the result
     */
    public static void print(PrintWriter out, Result r) {
        out.printf(Locale.ROOT, "%-4s robots=%-4d sensors=%-11s clients=%d load_s=%.3f read_s=%.3f build_s=%.3f connect_s=%.3f"
                        + " steps=%d s=%.2f steps_per_s=%.1f x_realtime=%.2f robot_steps_per_s=%.0f%n",
                r.run(), r.robots(), r.sensors().label(), r.clients(), r.load().seconds(), r.load().readNanos() / 1e9,
                r.load().buildNanos() / 1e9, r.load().connectNanos() / 1e9, r.steps(), r.seconds(), r.stepsPerSecond(),
                r.realtimeFactor(), r.robotStepsPerSecond());
        for (JvmMemory.Report m : r.memory()) {
            out.printf(Locale.ROOT, "mem  robots=%-4d sensors=%-11s jvm=%-7s %s%n", r.robots(), r.sensors().label(), m.jvm(),
                    JvmMemory.fields(m.figures()));
        }
        for (WindowReport w : r.windows()) {
            if (w.windows().isEmpty()) {
                out.printf(Locale.ROOT, "win  run=%-4s robots=%-4d sensors=%-11s jvm=%-7s windows=%s%n", r.run(), r.robots(),
                        r.sensors().label(), w.jvm(), JvmMemory.UNAVAILABLE);
            }
            for (StepWindows.Window x : w.windows()) {
                out.printf(Locale.ROOT, "win  run=%-4s robots=%-4d sensors=%-11s jvm=%-7s steps=%d-%d steps_per_s=%.1f"
                                + " cpu_us_per_step=%.1f alloc_kb_per_step=%.2f%s%n", r.run(), r.robots(), r.sensors().label(),
                        w.jvm(), x.from(), x.to(), x.stepsPerSecond(), x.cpuMicrosPerStep(), x.allocatedKibPerStep(),
                        x.stalled() < 0 ? "" : " stalled=" + x.stalled());
            }
        }
        out.flush();
    }

    /**
     * Prints the median of repeated runs of one kind, robot count and sensors, as one line: the
     * medians of the load time and of the step rate, and the range of × real time.
     *
     * @param out  where
     * @param runs the results, at least one
     */
    public static void printMedian(PrintWriter out, List<Result> runs) {
        List<Result> byRate = new ArrayList<>(runs);
        byRate.sort(Comparator.comparingDouble(Result::stepsPerSecond));
        List<Double> loads = new ArrayList<>(runs.stream().map(r -> r.load().seconds()).toList());
        loads.sort(null);
        Result m = byRate.get(byRate.size() / 2);
        out.printf(Locale.ROOT, "%-4s robots=%-4d sensors=%-11s clients=%d median_of=%d load_s=%.3f steps_per_s=%.1f"
                        + " x_realtime=%.2f x_realtime_min=%.2f x_realtime_max=%.2f robot_steps_per_s=%.0f%n",
                m.run(), m.robots(), m.sensors().label(), m.clients(), runs.size(), loads.get(loads.size() / 2),
                m.stepsPerSecond(), m.realtimeFactor(), byRate.get(0).realtimeFactor(),
                byRate.get(byRate.size() - 1).realtimeFactor(), m.robotStepsPerSecond());
        out.flush();
    }
}
