package robosim.experiment;

import java.io.IOException;
import java.lang.reflect.Method;
import java.net.InetAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import robosim.comms.CommsSettings;
import robosim.env.core.Simulation;
import robosim.env.net.Access;
import robosim.env.net.Departure;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunEnding;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.World;
import robosim.experiment.RunRobots.RunFailure;
import robosim.experiment.RunSpec.CommsPlan;
import robosim.experiment.RunSpec.Link;
import robosim.experiment.RunSpec.ProgramPlan;
import robosim.protocol.RunSecret;
import robosim.protocol.recording.RecordingWriter;

/**
 * Runs one run of a sweep in this JVM: makes its world, starts an Environment on loopback (behind a
 * fresh run secret), starts its robots (threads over the in-process link, or JVMs of their own), runs
 * it to its end and returns its record. Whatever goes wrong becomes a failed record with the reason:
 * one run never takes the sweep down. So does what would make the row depend on the machine rather
 * than on the programs: a robot dropped for missing its step deadline, or lost.
 */
public final class RunExecutor {
    private final Experiment experiment;
    private final String fingerprint;
    private final Path out;
    private final ClassLoader loader;
    private final RobotJvms jvms;
    private Link everyLink;

    /**
     * @param experiment  the experiment
     * @param fingerprint its runs' fingerprint
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
        RunWorlds.Made made = RunWorlds.make(run, out);
        World world = made.world();
        Simulation sim = new Simulation(world, run.seed());
        sim.setCommsSettings(comms(sim.commsSettings(), run.comms()));
        RunRobots robots = new RunRobots(loader, jvms, Thread.currentThread());
        List<Method> mains = new ArrayList<>();
        for (ProgramPlan p : run.programs()) {
            mains.add(everyLinkOf(p) == Link.IN_PROCESS ? robots.main(p.className()) : null);
        }
        String secret = RunSecret.create();
        ServerOptions options = ServerOptions.loopback().withMaxSteps(run.steps()).withAccess(Access.secret(secret))
                .withThreads(1);
        RecordingWriter recorder = null;
        RunReport report = null;
        try (EnvironmentServer server = new EnvironmentServer(sim, options)) {
            server.bind();
            if (recording != null) {
                Files.createDirectories(recording.toAbsolutePath().getParent());
                recorder = RecordingWriter.create(recording, false);
                server.addSnapshotListener(recorder);
            }
            server.admitInProcess();
            List<String> names = world.robots().stream().map(r -> r.name()).toList();
            int next = 0;
            for (int k = 0; k < run.programs().size(); k++) {
                ProgramPlan p = run.programs().get(k);
                int count = p.count() < 0 ? names.size() - next : p.count();
                for (int i = 0; i < count; i++) {
                    String robot = names.get(next++);
                    if (everyLinkOf(p) == Link.IN_PROCESS) {
                        List<String> args = new ArrayList<>(List.of(robot, "127.0.0.1",
                                Integer.toString(server.robotPort())));
                        args.addAll(p.args());
                        robots.startThread(robot, mains.get(k), args);
                    } else {
                        robots.startJvm(p.className(), robot, server.robotPort(), secret, out.resolve("logs")
                                .resolve(String.format(Locale.ROOT, "run-%06d-%s.log", run.index(), robot)), p.args());
                    }
                }
            }
            robots.arm();
            try {
                report = server.run();
            } catch (InterruptedException e) {
                if (robots.failure() == null) {
                    throw e;
                }
            } finally {
                robots.disarm();
            }
        } finally {
            robots.finish();
            if (recorder != null) {
                recorder.close();
            }
        }
        if (report == null) {
            throw new RunFailure(robots.failure() + "; the run was stopped");
        }
        double wall = (System.nanoTime() - start) / 1e9;
        Map<String, Object> metrics = Metrics.of(report, world, made.lowerBound(), experiment.aggregates(), wall,
                experiment.factorNames());
        String failure = robots.failure();
        if (failure == null) {
            failure = machineDependent(report);
        }
        if (failure == null && recorder != null && recorder.failure() != null) {
            failure = "the recording " + recording + " failed: " + recorder.failure().getMessage();
        }
        return new RunRecord(experiment.name(), fingerprint, run.index(), run.factors(), run.replicate(), run.seed(),
                failure == null ? RunRecord.OK : RunRecord.FAILED, failure, metrics, Metrics.robots(report), host(),
                report.wallNanos() / 1e9);
    }

    private Link everyLinkOf(ProgramPlan p) {
        return everyLink != null ? everyLink : p.link();
    }

    /**
     * @return why the run's row would depend on the machine (a robot dropped for missing its step
     *         deadline, or lost), or null
     */
    private static String machineDependent(RunReport report) {
        for (Departure d : report.departures()) {
            if (d.kind() != Departure.Kind.LEFT) {
                return "robot " + d.robot() + " " + d.describe() + ": a robot that misses its step deadline makes the"
                        + " run depend on the machine's speed";
            }
        }
        return null;
    }

    private static CommsSettings comms(CommsSettings c, CommsPlan p) {
        return new CommsSettings(p.range() == null ? c.maxRange() : p.range(),
                p.wallsBlock() == null ? c.wallsBlock() : p.wallsBlock(),
                p.latency() == null ? c.latencySteps() : p.latency(),
                p.loss() == null ? c.lossProbability() : p.loss(), c.maxMessageBytes());
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

    static String host() {
        try {
            return InetAddress.getLocalHost().getHostName();
        } catch (IOException e) {
            return "unknown";
        }
    }
}
