package robosim.env.net;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import robosim.env.threads.PooledParallel;
import robosim.env.core.RobotSummary;
import robosim.env.core.Simulation;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.inprocess.InProcessPorts;
import robosim.protocol.recording.SnapshotListener;
import robosim.protocol.recording.SnapshotListeners;

/**
 * The Environment on the network: accepts robots and viewers, waits for every robot the world
 * names, then drives lockstep steps: it sends each robot its time step and state, waits (up to the
 * step deadline) for every robot's requests for that step, advances the {@link Simulation}, and
 * sends the new snapshot to the viewers. Between two steps it carries out what control clients
 * asked for ({@link RunControl}: pause, step, pace, move, remove, stop).
 *
 * <p>One thread does it all: the step loop serves every connection through one selector between
 * steps, so no thread handoff stands between a robot's requests and the next step. Only inside a
 * step does the simulation share out the robots' sensor readings among {@link ServerOptions#threads}
 * workers, and the step returns once all are read. A peer that breaks the protocol is closed with
 * one log line and the run goes on for the others.
 */
public final class EnvironmentServer implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(EnvironmentServer.class.getName());
    /**
     * How often a paused run (or one with no robot) looks up from waiting, ms: well within
     * {@link TimeStepSender#KEEP_ALIVE_MS}.
     */
    static final long PAUSED_WAKE_MS = 250;

    private final ServerOptions options;
    private final MessageCodec codec = new MessageCodec();
    private final SessionRules rules;
    private final RunControl control;
    private final PooledParallel workers;
    private final Doorway doorway;
    private final SnapshotListeners listeners = new SnapshotListeners();
    private final TimeStepSender sender;
    private final ConnectionPump pump;
    private final ProgressReports progress;
    private InProcessPorts.Registration inProcessPort;

    /**
     * @param sim     the simulation to drive; it reads its robots' sensors on the server's
     *                {@link ServerOptions#threads} threads until the server is closed, then on the
     *                calling thread
     * @param options how to run
     */
    public EnvironmentServer(Simulation sim, ServerOptions options) {
        if (sim.robotNames().size() > options.limits().maxRobots()) {
            throw new IllegalArgumentException("world " + sim.world().name() + " names " + sim.robotNames().size()
                    + " robots, more than this Environment admits (" + options.limits().maxRobots() + ", --max-robots)");
        }
        this.options = options;
        this.rules = new SessionRules(sim, options.access(), options.limits());
        this.control = new RunControl(rules.run(), rules, options.limits().maxRobots(), rules.limited());
        rules.routeControlTo(control);
        this.doorway = new Doorway(options, codec, rules);
        this.progress = new ProgressReports(rules, options);
        this.workers = new PooledParallel(options.threads());
        this.sender = new TimeStepSender(codec, workers);
        this.pump = new ConnectionPump(doorway, rules, progress, sender);
        // the pace is the run's from the start: a status asked for while robots connect says it truly
        control.startPace(options.realtime() ? 1 : 0);
        sim.setParallel(workers);
    }

    /** @return the simulation run now: a control client's restart or load replaces it */
    private Simulation sim() {
        return rules.sim();
    }

    /**
     * Opens both listening sockets.
     *
     * @throws IOException           if a port cannot be bound
     * @throws IllegalStateException if the address is not a loopback address and the run has no
     *                               secret: anyone who could reach the ports could join, watch and change the run
     */
    public void bind() throws IOException {
        pump.bind();
        // from now the log's lines can be sent to the control clients that follow them
        rules.log().install();
    }

    /**
     * Adds a listener, such as a recorder, that follows the run as viewers do: it is given the
     * world and the snapshot of step 0 when the run starts, every snapshot after its step, the end, and
     * is closed when the run ends or the server closes. A listener that fails is logged and
     * dropped; the run goes on.
     *
     * @param listener the listener; add it before {@link #run()}
     */
    public void addSnapshotListener(SnapshotListener listener) {
        listeners.add(listener);
    }

    /**
     * Has the run followed by a launcher that shows its progress (see {@link RunProgress}).
     *
     * @param listener   called on the step loop's thread, at most once per interval; null for none
     * @param intervalMs the shortest time between two calls, ms; set it before {@link #run()}
     */
    public void setProgress(RunProgress listener, long intervalMs) {
        progress.follow(listener, intervalMs);
    }

    /**
     * Lets robots of this JVM whose runtime chooses in-process links reach this Environment
     * without TCP, at the loopback address and its robot port ({@link InProcessPorts}): the same
     * hellos, steps and byes, as objects. Call it after {@link #bind()}; the port is unregistered
     * when the server closes.
     *
     * @throws IllegalStateException if another Environment of this JVM registered the same port
     */
    public void admitInProcess() {
        inProcessPort = InProcessPorts.register(robotPort(), doorway.inProcess());
    }

    /** @return how many in-process links robot runtimes of this JVM have opened so far (see {@link #admitInProcess}) */
    public int inProcessLinks() {
        return doorway.inProcess().opened();
    }

    /** @return the port robots connect to */
    public int robotPort() {
        return doorway.robotPort();
    }

    /** @return the port viewers connect to */
    public int viewerPort() {
        return doorway.viewerPort();
    }

    /**
     * Waits for the world's robots, runs, and reports.
     *
     * @return how the run ended
     * @throws InterruptedException  if interrupted
     * @throws IllegalStateException if the robots do not all connect in time
     */
    public RunReport run() throws InterruptedException {
        awaitRobots();
        long connected = System.nanoTime();
        startRun();
        long started = System.nanoTime();
        EndOfRun end = loop();
        String reason = end.reason();
        List<Departure> departures = rules.departures();
        List<String> absent = absent(departures);
        long wall = System.nanoTime() - started;
        listeners.end(Bye.DONE + reason);
        listeners.close();
        for (Connection c : doorway.connections()) {
            c.sendAndClose(new Bye(Bye.DONE + reason));
        }
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(2);
        while (doorway.connections().stream().anyMatch(c -> !c.isClosed()) && System.nanoTime() < deadline) {
            pump(deadline);
        }
        List<RobotSummary> summaries = new ArrayList<>();
        for (String name : sim().robotNames()) {
            summaries.add(sim().summary(name));
        }
        return new RunReport(sim().stepCount(), sim().timeMs(), reason, end.ending(), summaries, wall, sim().find(),
                connected, departures, rules.joins(), absent, sim().metrics(), sim().endRequest());
    }

    /**
     * @return the robots not connected at the end that never went either: they never came to this
     *         run (an open world's, or the robots of a run that a restart or load began)
     */
    private List<String> absent(List<Departure> departures) {
        List<String> absent = new ArrayList<>();
        for (String name : sim().robotNames()) {
            if (!rules.connectedRobots().containsKey(name) && departures.stream().noneMatch(d -> d.robot().equals(name))) {
                absent.add(name);
            }
        }
        return absent;
    }

    /**
     * The robots are there: the run starts, and its world and step 0 go to the listeners, and step 0
     * again to the viewers, every robot connected.
     */
    private void startRun() {
        rules.start();
        LOG.info(() -> "all robots connected; running world " + sim().world().name() + " (seed " + sim().seed() + ")");
        if (rules.takeWorldChanged()) {
            // robots spawned before the start: the viewers attached before them learn of them now
            rules.broadcastSnapshot(sim().description(), codec);
        }
        listeners.world(sim().description());
        listeners.snapshot(sim().snapshot());
        // the viewers attached while robots were connecting saw step 0 as it was then: they see the start
        rules.broadcastSnapshot(sim().snapshot(), codec);
    }

    /**
     * Carries out a {@code restart} or {@code load} at a step boundary: the run's robots are told why
     * and disconnected, a new simulation of the world with the same seed takes its place, the viewers
     * are sent its world and step 0, and the new run starts when its robots have connected. There is
     * no connect timeout now: the user drives, and may stop, restart or load again meanwhile.
     *
     * @return the Environment's end while waiting (a stop), or null once the new run has started
     */
    private EndOfRun switchRun(RunControl.Switch first) throws InterruptedException {
        RunControl.Switch s = first;
        while (s != null) {
            Simulation next = new Simulation(s.world(), sim().seed(), workers);
            String why = s.why();
            LOG.info(() -> why + ": world " + next.world().name() + " runs from step 0 once its robots connect");
            rules.replace(next, "the run ended for a " + why + "; connect again to join the new run");
            rules.broadcastSnapshot(next.description(), codec);
            rules.broadcastSnapshot(next.snapshot(), codec);
            s.answer(why + ": world " + next.world().name() + " (seed " + next.seed() + ") waits for its robots");
            s = null;
            progress.waitingUntimedSince(System.nanoTime());
            while (!rules.allConnected() || rules.viewerCount() < options.waitViewers()) {
                EndOfRun end = control.atBoundary();
                if (end != null) {
                    return end;
                }
                s = control.takeSwitch();
                if (s != null) {
                    break;
                }
                progress.reportIfDue(RunProgress.Phase.CONNECTING, System.nanoTime());
                pump(System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(PAUSED_WAKE_MS));
            }
        }
        startRun();
        return null;
    }

    /** @return a time as seconds when it is whole seconds (as {@code env --connect-timeout} gives it), else ms */
    static String inUnitGiven(long ms) {
        return ms % 1000 == 0 ? ms / 1000 + " s" : ms + " ms";
    }

    private void awaitRobots() throws InterruptedException {
        long waitStarted = System.nanoTime();
        progress.waitingSince(waitStarted);
        long deadline = waitStarted + TimeUnit.MILLISECONDS.toNanos(options.connectTimeoutMs());
        while (!rules.allConnected() || rules.viewerCount() < options.waitViewers()) {
            long now = System.nanoTime();
            progress.reportIfDue(RunProgress.Phase.CONNECTING, now);
            if (now - deadline >= 0) {
                String who = rules.missing().isEmpty() ? "no robot (open world " + sim().world().name() + ")"
                        : "robots " + rules.missing();
                String why = who + " and " + Math.max(0,
                        options.waitViewers() - rules.viewerCount()) + " viewer(s) did not connect within "
                        + inUnitGiven(options.connectTimeoutMs()) + refusedClause();
                // the robots that came are told why the run they waited for will not start
                for (Connection c : doorway.connections()) {
                    c.sendAndClose(new Bye("the run did not start: " + why));
                }
                throw new IllegalStateException(why);
            }
            pump(deadline);
        }
    }

    /** @return {@code ; refused: r1 (presented no run secret), ...}, or nothing when none was refused */
    private String refusedClause() {
        Map<String, String> refused = rules.refusals();
        if (refused.isEmpty()) {
            return "";
        }
        List<String> each = new ArrayList<>();
        refused.forEach((who, why) -> each.add(who + " (" + why + ")"));
        return "; refused: " + String.join(", ", each);
    }

    private EndOfRun loop() throws InterruptedException {
        progress.runningSince(System.nanoTime());
        while (true) {
            if (progress.following()) {
                // the one look at the clock a step takes for the progress, and only when someone follows it
                progress.reportIfDue(RunProgress.Phase.RUNNING, System.nanoTime());
            }
            EndOfRun end = EndConditions.ending(sim(), rules, options.maxSteps());
            if (end == null) {
                // control requests are carried out here, between steps, so the same requests at the same steps give the same run
                end = control.atBoundary();
            }
            RunControl.Switch next = end == null ? control.takeSwitch() : null;
            if (next != null) {
                end = switchRun(next);
            }
            if (end != null) {
                return end;
            }
            if (next != null) {
                continue;
            }
            long current = sim().stepCount() + 1;
            if (control.holding() || rules.connectedRobots().isEmpty()) {
                // paused, or no robot to run (a world that does not end when all have gone waits for
                // one to join): no step is open, so no deadline runs; the pump keeps the robots alive
                pump(System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(PAUSED_WAKE_MS));
                continue;
            }
            long now = System.nanoTime();
            long due = control.due(current, sim().world().stepMs(), now);
            if (now < due) {
                // waking for a request too, so a pause or a new pace need not wait out a slow pace
                pump(due);
                continue;
            }
            Map<String, List<Command>> commands = collect(current);
            sim().step(commands);
            control.stepped();
            publish();
        }
    }

    /**
     * Sends the viewers and listeners the snapshot after a step, with the robots that joined or went
     * since the one before, and before it the world again when a robot was added to it (the snapshot
     * then carries every robot's drawings, not only the changed ones). The snapshot
     * is built only when someone watches: benchmarks and headless runs skip it.
     */
    private void publish() {
        boolean worldChanged = rules.takeWorldChanged();
        List<Snapshot.Event> events = rules.takeEvents();
        if (rules.viewerCount() == 0 && listeners.size() == 0) {
            return;
        }
        Snapshot snapshot = sim().snapshot().withEvents(events);
        if (worldChanged) {
            WorldDescription world = sim().description();
            rules.broadcastSnapshot(world, codec);
            listeners.world(world);
            // a viewer forgets the drawings with the world it replaces: the snapshot after it carries them all
            snapshot = snapshot.withDrawings(sim().drawings());
        }
        rules.broadcastSnapshot(snapshot, codec);
        listeners.snapshot(snapshot);
    }

    private Map<String, List<Command>> collect(long current) throws InterruptedException {
        rules.openStep(current);
        sender.send(sim(), rules.connectedRobots(), current);
        // a robot whose connection failed as its state was sent is lost now, not waited for
        rules.reapClosed();
        long opened = System.nanoTime();
        progress.waitingSince(opened);
        // welcomes are said on this thread before a step opens (a robot welcomed during a step takes
        // part from the next), so the deadline counts from after the last welcome
        long deadline = opened + TimeUnit.MILLISECONDS.toNanos(options.stepTimeoutMs());
        // robots in their first steps (loading classes, warming up) may take longer: see ServerOptions
        long firstDeadline = opened + TimeUnit.MILLISECONDS.toNanos(options.stepTimeoutMs(1));
        while (!rules.waitingFor().isEmpty()) {
            long now = System.nanoTime();
            progress.reportIfDue(RunProgress.Phase.STEP_HELD, now);
            if (now - deadline >= 0) {
                Set<String> late = new LinkedHashSet<>(rules.waitingFor());
                boolean anyStarting = false;
                for (String name : late) {
                    long own = rules.robotStep(name, current);
                    if (own <= ServerOptions.FIRST_STEPS && now - firstDeadline < 0) {
                        anyStarting = true;
                        continue;
                    }
                    rules.drop(name, lateReason(current, own));
                }
                if (!anyStarting) {
                    break;
                }
                deadline = firstDeadline;
                progress.stepLimit(options.stepTimeoutMs(1));
            }
            pump(deadline);
        }
        return rules.closeStep();
    }

    /** @return why a robot is dropped that sent nothing for a step, naming the option that would give it longer */
    private String lateReason(long step, long robotStep) {
        long ms = options.stepTimeoutMs(robotStep);
        String option = ms > options.stepTimeoutMs() ? "one of its first " + ServerOptions.FIRST_STEPS
                + " steps; env --first-steps-timeout gives them longer" : "env --step-timeout gives it longer";
        return "it did not send its requests for step " + step + " within " + ms + " ms (" + option + ")";
    }

    private void pump(long deadlineNanos) throws InterruptedException {
        pump.pump(deadlineNanos);
    }

    /** Stops listening and closes every connection. */
    @Override
    public void close() {
        if (inProcessPort != null) {
            inProcessPort.close();
        }
        // a simulation used after this reads on its caller's thread: a closed pool runs its loops there
        workers.close();
        listeners.close();
        rules.log().close();
        pump.close();
    }
}
