package robosim.experiment;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import robosim.comms.CommsSettings;
import robosim.env.core.Simulation;
import robosim.env.net.Access;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunEnding;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.World;
import robosim.env.world.maze.GoldBound;
import robosim.env.world.maze.Maze;
import robosim.env.world.maze.MazeWorldWriter;
import robosim.env.world.xml.WorldReader;
import robosim.experiment.RunSpec.CommsPlan;
import robosim.experiment.RunSpec.FilePlan;
import robosim.experiment.RunSpec.Link;
import robosim.experiment.RunSpec.MazePlan;
import robosim.experiment.RunSpec.ProgramPlan;
import robosim.params.RobotParameterFiles;
import robosim.protocol.RunSecret;
import robosim.protocol.recording.RecordingWriter;

/**
 * Runs one run of a sweep in this JVM: makes its world, starts an Environment on loopback (behind a
 * fresh run secret), starts its robots (threads over the in-process link, or JVMs of their own), runs
 * it to its end and returns its record. Whatever goes wrong becomes a failed record with the reason:
 * one run never takes the sweep down.
 */
public final class RunExecutor {
    /** How long programs may go on once the run is over, ms: they end as their robots are told so. */
    static final long GRACE_MS = 2_000;

    private final Experiment experiment;
    private final String fingerprint;
    private final Path out;
    private final ClassLoader loader;
    private final RobotJvms jvms;
    private Link everyLink;

    /**
     * @param experiment  the experiment
     * @param fingerprint its file's fingerprint
     * @param out         the results folder (worlds, logs and recordings go under it)
     * @param loader      where the programs' classes come from
     * @param jvms        how to start a program in a JVM of its own, or null if none may be
     */
    public RunExecutor(Experiment experiment, String fingerprint, Path out, ClassLoader loader, RobotJvms jvms) {
        this.experiment = experiment;
        this.fingerprint = fingerprint;
        this.out = out;
        this.loader = loader;
        this.jvms = jvms;
    }

    /**
     * @param link how every program's robots reach the Environment, whatever the file says; null for
     *             what it says
     * @return this
     */
    public RunExecutor withEveryLink(Link link) {
        this.everyLink = link;
        return this;
    }

    /**
     * @param run       the run
     * @param recording where to record it, or null
     * @return its record, failed with the reason if it could not run to its end
     * @throws InterruptedException if interrupted
     */
    public RunRecord execute(RunSpec run, Path recording) throws InterruptedException {
        long start = System.nanoTime();
        try {
            return attempt(run, recording, start);
        } catch (RunFailure e) {
            return failed(run, e.getMessage(), start);
        } catch (IOException | RuntimeException e) {
            return failed(run, e.getClass().getSimpleName() + ": " + e.getMessage(), start);
        }
    }

    private RunRecord attempt(RunSpec run, Path recording, long start) throws IOException, InterruptedException {
        Made made = world(run);
        World world = made.world;
        Simulation sim = new Simulation(world, run.seed());
        sim.setCommsSettings(comms(sim.commsSettings(), run.comms()));
        List<String> robots = world.robots().stream().map(r -> r.name()).toList();
        List<Method> mains = new ArrayList<>();
        for (ProgramPlan p : run.programs()) {
            mains.add(main(p.className()));
        }
        String secret = RunSecret.create();
        ServerOptions options = ServerOptions.loopback().withMaxSteps(run.steps()).withAccess(Access.secret(secret))
                .withThreads(1);
        Map<String, Throwable> failures = new java.util.concurrent.ConcurrentHashMap<>();
        List<Thread> threads = new ArrayList<>();
        List<Process> processes = new ArrayList<>();
        RecordingWriter recorder = null;
        RunReport report = null;
        Interrupter stopper = new Interrupter(Thread.currentThread());
        try (EnvironmentServer server = new EnvironmentServer(sim, options)) {
            server.bind();
            if (recording != null) {
                Files.createDirectories(recording.toAbsolutePath().getParent());
                recorder = RecordingWriter.create(recording, false);
                server.addSnapshotListener(recorder);
            }
            server.admitInProcess();
            int next = 0;
            for (int k = 0; k < run.programs().size(); k++) {
                ProgramPlan p = run.programs().get(k);
                int count = p.count() < 0 ? robots.size() - next : p.count();
                for (int i = 0; i < count; i++) {
                    String robot = robots.get(next++);
                    List<String> args = new ArrayList<>(List.of(robot, "127.0.0.1", Integer.toString(server.robotPort())));
                    args.addAll(p.args());
                    if ((everyLink != null ? everyLink : p.link()) == Link.IN_PROCESS) {
                        threads.add(startThread(robot, mains.get(k), args, failures, stopper));
                    } else {
                        if (jvms == null) {
                            throw new RunFailure("program " + p.className() + " asks for link: jvm, but this runner"
                                    + " cannot start JVMs");
                        }
                        Path log = out.resolve("logs").resolve(String.format(Locale.ROOT, "run-%06d-%s.log",
                                run.index(), robot));
                        Files.createDirectories(log.getParent());
                        processes.add(jvms.start(p.className(), robot, server.robotPort(), secret, log, p.args()));
                    }
                }
            }
            stopper.arm();
            try {
                report = server.run();
            } catch (InterruptedException e) {
                if (failures.isEmpty()) {
                    throw e;
                }
            } finally {
                stopper.disarm();
            }
        } finally {
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(GRACE_MS);
            for (Thread t : threads) {
                t.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
            }
            stop(processes);
            if (recorder != null) {
                recorder.close();
            }
        }
        if (report == null) {
            Map.Entry<String, Throwable> first = failures.entrySet().iterator().next();
            throw new RunFailure("robot " + first.getKey() + "'s program failed: " + describe(first.getValue())
                    + "; the run was stopped");
        }
        double wall = (System.nanoTime() - start) / 1e9;
        Map<String, Object> metrics = Metrics.of(report, world, made.lowerBound, experiment.aggregates(), wall);
        List<RunRecord.RobotFigures> figures = Metrics.robots(report);
        String failure = null;
        if (!failures.isEmpty()) {
            Map.Entry<String, Throwable> first = failures.entrySet().iterator().next();
            failure = "robot " + first.getKey() + "'s program failed: " + describe(first.getValue());
        } else if (recorder != null && recorder.failure() != null) {
            failure = "the recording " + recording + " failed: " + recorder.failure().getMessage();
        }
        return new RunRecord(experiment.name(), fingerprint, run.index(), run.factors(), run.replicate(), run.seed(),
                failure == null ? RunRecord.OK : RunRecord.FAILED, failure, metrics, figures, host(),
                report.wallNanos() / 1e9);
    }

    /** A world made for a run, with its maze's lower bound (null for a world file or a maze without gold). */
    private record Made(World world, Long lowerBound) {
    }

    private Made world(RunSpec run) throws IOException {
        int wanted = 0;
        boolean rest = false;
        for (ProgramPlan p : run.programs()) {
            if (p.count() < 0) {
                rest = true;
            } else {
                wanted += p.count();
            }
        }
        if (run.world() instanceof MazePlan m) {
            if (rest) {
                throw new RunFailure("a maze world has the robots the programs ask for: give every program a count");
            }
            Maze maze = Maze.generate(m.width(), m.height(), m.mazeSeed());
            Path params = RobotParameterFiles.resolve(m.robotFile()).toAbsolutePath();
            Path dir = out.resolve("worlds");
            Files.createDirectories(dir);
            String xml = MazeWorldWriter.write(maze, String.format(Locale.ROOT, "maze-%dx%d-%d", m.width(), m.height(),
                    m.mazeSeed()), m.cellSize(), wanted, params.toString().replace('\\', '/'));
            // named by its text: runs at once that need the same maze with other robots never share a file
            Path file = dir.resolve(String.format(Locale.ROOT, "maze-%dx%d-%d-%s.xml", m.width(), m.height(),
                    m.mazeSeed(), ExperimentFiles.fingerprint(xml)));
            writeOnce(file, xml);
            World world = properties(WorldReader.read(file), m.properties());
            Long bound = world.gold() == null || wanted == 0 ? null : GoldBound.steps(maze, world, m.cellSize());
            return new Made(world, bound);
        }
        FilePlan f = (FilePlan) run.world();
        World world = WorldReader.read(f.file());
        int named = world.robots().size();
        if (wanted > named || (!rest && wanted == 0)) {
            throw new RunFailure("world " + f.file() + " names " + named + " robot(s); the programs ask for " + wanted);
        }
        return new Made(properties(rest ? world : world.withFirstRobots(wanted), f.properties()), null);
    }

    /** Writes a world file many workers may write at once: the same text, so the first one's stays. */
    private static void writeOnce(Path file, String xml) throws IOException {
        if (Files.exists(file) && Files.readString(file, StandardCharsets.UTF_8).equals(xml)) {
            return;
        }
        Path tmp = Files.createTempFile(file.getParent(), ".maze-", ".tmp");
        try {
            Files.writeString(tmp, xml, StandardCharsets.UTF_8);
            Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING,
                    java.nio.file.StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    private static World properties(World world, Map<String, String> set) {
        if (set.isEmpty()) {
            return world;
        }
        Map<String, String> all = new LinkedHashMap<>(world.properties());
        all.putAll(set);
        return world.withProperties(all);
    }

    private static CommsSettings comms(CommsSettings c, CommsPlan p) {
        return new CommsSettings(p.range() == null ? c.maxRange() : p.range(),
                p.wallsBlock() == null ? c.wallsBlock() : p.wallsBlock(),
                p.latency() == null ? c.latencySteps() : p.latency(),
                p.loss() == null ? c.lossProbability() : p.loss(), c.maxMessageBytes());
    }

    private Method main(String className) {
        try {
            Method m = Class.forName(className, true, loader).getMethod("main", String[].class);
            if (!Modifier.isStatic(m.getModifiers())) {
                throw new RunFailure("program " + className + "'s main is not static");
            }
            return m;
        } catch (ClassNotFoundException | NoSuchMethodException | LinkageError e) {
            throw new RunFailure("program " + className + " is no class with a public static main(String[]) on"
                    + " RoboSim's classpath or --classpath (" + e + ")");
        }
    }

    private Thread startThread(String robot, Method main, List<String> args, Map<String, Throwable> failures,
                               Interrupter stopper) {
        Thread t = new Thread(() -> {
            Throwable failure = null;
            try {
                main.invoke(null, (Object) args.toArray(String[]::new));
            } catch (InvocationTargetException e) {
                failure = e.getCause();
            } catch (IllegalAccessException | RuntimeException e) {
                failure = e;
            }
            if (failure != null) {
                failures.putIfAbsent(robot, failure);
                // a robot whose program died may never connect or may stall every step: the run stops now
                stopper.interrupt();
            }
        }, "robot-program-" + robot);
        t.setContextClassLoader(loader);
        t.setDaemon(true);
        t.start();
        return t;
    }

    private static void stop(List<Process> processes) throws InterruptedException {
        for (Process p : processes) {
            if (!p.waitFor(10, TimeUnit.SECONDS)) {
                p.destroy();
                if (!p.waitFor(5, TimeUnit.SECONDS)) {
                    p.destroyForcibly().waitFor(5, TimeUnit.SECONDS);
                }
            }
        }
    }

    private RunRecord failed(RunSpec run, String reason, long start) {
        Map<String, Object> metrics = new LinkedHashMap<>();
        metrics.put(Metrics.ENDING, RunEnding.FAILED.wireName());
        metrics.put(Metrics.WALL_TIME, Math.round((System.nanoTime() - start) / 1e6) / 1000.0);
        return new RunRecord(experiment.name(), fingerprint, run.index(), run.factors(), run.replicate(), run.seed(),
                RunRecord.FAILED, reason, metrics, List.of(), host(), 0);
    }

    /**
     * @param run    the run
     * @param reason why it failed
     * @return a failed record of it, for a runner that lost the run (its worker died)
     */
    public RunRecord lost(RunSpec run, String reason) {
        return new RunRecord(experiment.name(), fingerprint, run.index(), run.factors(), run.replicate(), run.seed(),
                RunRecord.FAILED, reason, Map.of(Metrics.ENDING, RunEnding.FAILED.wireName()), List.of(), host(), 0);
    }

    private static String describe(Throwable t) {
        StringWriter s = new StringWriter();
        s.append(t.toString());
        StackTraceElement[] trace = t.getStackTrace();
        if (trace.length > 0) {
            s.append(" at ").append(trace[0].toString());
        }
        return s.toString();
    }

    static String host() {
        try {
            return InetAddress.getLocalHost().getHostName();
        } catch (IOException e) {
            return "unknown";
        }
    }

    /**
     * Interrupts the thread running the Environment while, and only while, the run is under way: a
     * program that fails after the run has ended leaves the thread alone.
     */
    private static final class Interrupter {
        private final Thread runner;
        private boolean armed;

        Interrupter(Thread runner) {
            this.runner = runner;
        }

        synchronized void arm() {
            armed = true;
        }

        /** The run is over: no interrupt comes after this, and none that came before it is left pending. */
        synchronized void disarm() {
            armed = false;
            Thread.interrupted();
        }

        synchronized void interrupt() {
            if (armed) {
                runner.interrupt();
            }
        }
    }

    /** A run that cannot go on, with the reason its record gives. */
    private static final class RunFailure extends RuntimeException {
        private static final long serialVersionUID = 1L;

        RunFailure(String message) {
            super(message);
        }
    }
}
