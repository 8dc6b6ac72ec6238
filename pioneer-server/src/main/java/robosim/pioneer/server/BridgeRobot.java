package robosim.pioneer.server;

import java.io.IOException;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.function.IntConsumer;
import java.util.function.Supplier;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.hw.AbstractRobot;
import robosim.hw.RobotSensorResponse;
import robosim.pioneer.GripperPacket;
import robosim.pioneer.LaserPacket;
import robosim.pioneer.PioneerPacket;
import robosim.pioneer.SimStat;
import robosim.protocol.Command;
import robosim.protocol.LaserReading;
import robosim.protocol.LogLimiter;
import robosim.protocol.RobotState;
import robosim.protocol.TruePose;

/**
 * A world robot driven by an ARIA client: an ordinary robot client of the Environment, with its own
 * HardwareSimulator, whose program is the client's commands. Each step it sends what the client
 * asked since the last one ({@link PendingCommands}), yields, and answers with a status packet (and
 * the gripper's and the laser's packets, and SIMSTAT, when asked). While a client is attached, each step waits until
 * its time has come in real time, since ARIA keeps wall-clock time; with none attached the robot
 * stands still and does not hold the run back. It stays in the run between clients; each new
 * client finds the odometry at (0, 0, 0), as on a Pioneer that was just switched on.
 *
 * <p>A client is attached at once, before the Environment has welcomed the robot: the client's
 * handshake and commands never wait on the Environment. Until the run steps (while the robot waits
 * for its welcome, while the run waits for its other robots, while it is paused or held back for
 * {@value #STANDBY_AFTER_MS} ms) the client gets a status packet every cycle of the robot standing
 * where it is ({@link Standby}), and its commands wait for the robot's first step.
 */
final class BridgeRobot extends AbstractRobot {
    /** What a client attached before the welcome is sent: standing at the odometry's origin, nothing sensed. */
    private static final RobotState BEFORE_WELCOME = new RobotState(0, 0, 0, 0, 0, 0, 0, 0, 0, false, 0);

    private static final Logger LOG = Logger.getLogger(BridgeRobot.class.getName());
    private static final LogLimiter LIMITED = new LogLimiter(LOG);
    /** How long the run may go without a step before the client gets the status of its robot standing, ms. */
    static final long STANDBY_AFTER_MS = 1000;

    private final ServedRobot served;
    private final PioneerPortOptions options;
    private final PendingCommands commands = new PendingCommands();
    private final CompletableFuture<Void> joined = new CompletableFuture<>();
    /** Guards who is attached, the welcome, and how the robot's part ends. */
    private final Object lock = new Object();
    private volatile Attached attached;
    private volatile boolean cancelled;
    /** A ResetToStart went with the last step's requests: the odometry restarts at the state it brings. */
    private volatile boolean resetAfterStep;
    private volatile int simStatMode;
    /** The robot's latest state, the welcome's before the first step; null until the welcome. */
    private volatile RobotState latest;
    /** Whether the world has a program find the motors enabled as it connects ({@code <world motors=...>}). */
    private volatile boolean motorsAtConnect;
    /** {@link System#nanoTime()} of the last step's status packet to a client; 0 before the first. */
    private volatile long lastReportNanos;
    /** Whether the robot's part in the run has ended, or it never joined: nothing is sent from then. */
    private volatile boolean done;
    private ClientLeft lastLeft;
    private Attached attachedAtEnd;
    private String failure;
    private long nextStepNanos;

    /** A client with its session and the robot's server state for it. */
    record Attached(PioneerSession session, CommandHandler handler, SipBuilder sips, LaserScan laser,
                    OdometryFrame frame) {
    }

    /**
     * How the last client went while the robot was in the run.
     *
     * @param step   the robot's last step then (0: before the run started)
     * @param reason why, as its session ended
     */
    record ClientLeft(long step, String reason) {
        /** @return how the run report says it */
        String describe() {
            return (step == 0 ? "its ARIA client left before the run started (" : "its ARIA client left after step "
                    + step + " (") + reason + "); the robot stood still from then to the end";
        }
    }

    BridgeRobot(ServedRobot served, String host, int port, PioneerPortOptions options) {
        super(served.name(), host, port, served.robotType(), served.parameters());
        this.served = served;
        this.options = options;
    }

    /**
     * Connects to the Environment on a thread of its own, which then runs the robot's steps, and
     * sends the status of the robot standing on another while the run does not step.
     *
     * @param secret the run secret, or null
     * @return done when the Environment has welcomed the robot, or failed with why not
     */
    CompletableFuture<Void> start(String secret) {
        Thread t = new Thread(() -> run(secret), "pioneer-bridge-" + served.name());
        t.setDaemon(true);
        t.start();
        Thread s = new Thread(new Standby(this), "pioneer-standby-" + served.name());
        s.setDaemon(true);
        s.start();
        return joined;
    }

    /** The port closes: the robot leaves the run, or does not join it. */
    void cancel() {
        cancelled = true;
        disconnect();
    }

    /** @return whether the Environment refused the robot or could not be reached: a new bridge may try again */
    boolean failedToJoin() {
        return joined.isCompletedExceptionally();
    }

    /** @return whether the robot was in the run and its part has ended: it does not come back */
    boolean hasLeftRun() {
        return joined.isDone() && !joined.isCompletedExceptionally() && done;
    }

    private void run(String secret) {
        try {
            connectPresenting(options.hardware(), secret);
            if (cancelled) {
                disconnect(); // the port closed meanwhile: the robot must not stay in the run unserved
                throw new IOException("the Pioneer port closed");
            }
        } catch (IOException | RuntimeException e) {
            fail("the Environment did not take robot " + served.name() + ": " + e.getMessage());
            joined.completeExceptionally(e);
            return;
        }
        RobotState welcome = state();
        synchronized (lock) {
            latest = welcome;
            motorsAtConnect = Boolean.TRUE.equals(welcome.motorsEnabled());
            Attached a = attached;
            if (a != null) {
                a.frame().resetAt(welcome.x(), welcome.y(), welcome.th()); // attached before the welcome
            }
        }
        joined.complete(null);
        try {
            while (isConnected()) {
                Attached a = attached;
                pace(a);
                watchdog(a);
                sleepSimulated(getStepMs());
                RobotState s = state();
                latest = s;
                if (a != null && a == attached && a.session().isOpen()) {
                    report(a, s);
                }
            }
        } catch (RuntimeException e) {
            // the bridge must not die silently: the robot leaves the run and its client is told below
            LOG.log(Level.WARNING, "robot " + served.name() + ": the bridge failed; the robot leaves the run", e);
            disconnect();
        }
        Attached a;
        synchronized (lock) {
            done = true;
            attachedAtEnd = attached;
            a = attached;
        }
        if (a != null) {
            a.session().end("the robot left the run: " + (getRunEnd() == null ? "?" : getRunEnd().describe()));
        }
    }

    private void fail(String why) {
        Attached a;
        synchronized (lock) {
            done = true;
            failure = why;
            a = attached;
        }
        LIMITED.warning("failures of robot " + served.name() + "'s bridge", () -> "robot " + served.name() + ": " + why);
        if (a != null) {
            a.session().end(why);
        }
    }

    /**
     * Carries the commands the client gave since the last step into this one, on the robot's
     * hardware thread as the step arrives, while the robot's code is yielded.
     */
    @Override
    protected void responded(RobotSensorResponse response) {
        super.responded(response);
        RobotState s = response.state();
        Attached a = attached;
        if (resetAfterStep) {
            resetAfterStep = false;
            if (a != null) {
                a.frame().resetAt(s.x(), s.y(), s.th());
            }
        }
        for (Command c : commands.drain()) {
            resetAfterStep |= c instanceof Command.ResetToStart;
            request(c);
        }
    }

    /** Waits until this step's time has come in real time, while a client is attached. */
    private void pace(Attached a) {
        long now = System.nanoTime();
        if (a == null || !options.realTime()) {
            nextStepNanos = now;
            return;
        }
        long step = getStepMs() * 1_000_000L;
        nextStepNanos += step;
        if (nextStepNanos < now - step) {
            nextStepNanos = now; // the run fell behind: start again from now rather than rush to catch up
        }
        long wait = nextStepNanos - now;
        if (wait > 0) {
            try {
                Thread.sleep(wait / 1_000_000, (int) (wait % 1_000_000));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private boolean watchdogTripped;

    /** A client silent for the watchdog time stops the robot, as a Pioneer's firmware does. */
    private void watchdog(Attached a) {
        if (a == null) {
            return;
        }
        boolean silent = a.session().silentMs() > options.watchdogMs();
        if (silent && !watchdogTripped) {
            LOG.warning(() -> "robot " + served.name() + ": the ARIA client has sent nothing for "
                    + options.watchdogMs() + " ms; the robot stops, as a Pioneer's watchdog stops it");
            commands.add(new Command.Stop());
        }
        watchdogTripped = silent;
    }

    private void report(Attached a, RobotState s) {
        PioneerSession session = a.session();
        session.send(a.sips().build(s, a.frame(), Boolean.TRUE.equals(s.motorsEnabled()), a.handler().sonarOn()).toPacket());
        lastReportNanos = System.nanoTime();
        sendGripper(a, s);
        for (LaserPacket p : a.laser().packets(s.get(LaserReading.PART).ranges())) {
            session.send(p.toPacket());
        }
        int mode = simStatMode;
        TruePose t = s.get(TruePose.PART);
        if (mode != 0 && t != null) {
            session.send(new SimStat(0, getStepMs(), options.realTime() ? getStepMs() : 0, getStepMs(),
                    (int) Math.round(t.x()), (int) Math.round(t.y()), 0, (int) Math.round(t.th())).toPacket());
            if (mode == 1) {
                simStatMode = 0;
            }
        }
    }

    /**
     * Sends the attached client the status of its robot standing, if the run has not stepped for it
     * lately: for {@link Standby}, once a cycle.
     *
     * @param now {@link System#nanoTime()}
     * @return false once nothing more is ever sent (the robot's part has ended, or it never joined)
     */
    boolean standBy(long now) {
        if (done) {
            return false;
        }
        Attached a = attached;
        long last = lastReportNanos;
        if (a == null || !a.session().isOpen() || last != 0 && now - last < STANDBY_AFTER_MS * 1_000_000L) {
            return true;
        }
        RobotState s = latest;
        if (s == null) {
            // before the welcome is handled: the odometry's origin, nothing sensed yet (not state(),
            // which may already hold the welcome's pose while the frame is still at the origin)
            s = BEFORE_WELCOME;
        }
        a.session().send(a.sips().standing(s, a.frame(), Boolean.TRUE.equals(s.motorsEnabled()),
                a.handler().sonarOn()).toPacket());
        sendGripper(a, s);
        for (LaserPacket p : a.laser().packets(s.get(LaserReading.PART).ranges())) {
            a.session().send(p.toPacket());
        }
        return true;
    }

    /** The gripper packet the client asked for, after the status packet of the same state. */
    private static void sendGripper(Attached a, RobotState s) {
        GripperPacket g = a.handler().gripperReports().next(s);
        if (g != null) {
            a.session().send(g.toPacket());
        }
    }

    /** @return ms between status packets: the world's step length, as the welcome gives it (the world file's before) */
    int sipCycleMs() {
        return latest != null ? getStepMs() : served.stepMs();
    }

    /**
     * Attaches a client that has just connected, without waiting on the Environment: the odometry
     * starts again at (0, 0, 0), the motors are as the world has a program find them (disabled
     * unless {@code <world motors="enabled">}, until the client's ENABLE 1), the sonar is on and the
     * laser off, as on a Pioneer just connected to. A client attached before the robot's welcome
     * finds the robot as the world places it, and the commands of a client that left before then
     * are forgotten. A robot whose part has ended, or that the Environment did not take, ends the
     * session at once, saying why.
     *
     * @param session the client's session
     * @param simExit what SIM_EXIT does when it is allowed
     */
    void attach(PioneerSession session, IntConsumer simExit) {
        OdometryFrame frame = new OdometryFrame();
        LaserScan laser = new LaserScan();
        CommandHandler handler = new CommandHandler(served.name(), served.parameters(), served.factors(), laser, frame,
                new SessionEffects(session, simExit, frame));
        Attached a = new Attached(session, handler, new SipBuilder(served.factors(), served.parameters().hasGripper()), laser, frame);
        String refusal = null;
        synchronized (lock) {
            if (done) {
                refusal = failure != null ? failure : "robot " + served.name() + "'s part in the run has ended";
            } else {
                RobotState s = latest;
                if (s != null) {
                    frame.resetAt(s.x(), s.y(), s.th());
                } else {
                    commands.clear();
                }
                commands.add(new Command.Stop());
                if (s != null) {
                    commands.add(new Command.SetMotors(motorsAtConnect));
                }
                commands.add(new Command.SetSonar(true));
                commands.add(laser.command(served.parameters().laserMaxRange()));
                simStatMode = 0;
                attached = a;
            }
        }
        if (refusal != null) {
            session.end(refusal);
            return;
        }
        session.attach(handler, () -> handler.config(served.name(), sipCycleMs(), (int) options.watchdogMs()),
                reason -> detach(a, reason));
    }

    private void detach(Attached a, String reason) {
        synchronized (lock) {
            if (attached != a) {
                return;
            }
            attached = null;
            commands.add(new Command.Stop());
            if (!done) {
                lastLeft = new ClientLeft(getStep(), reason);
            }
        }
    }

    /**
     * @return how the robot stood without a client to the end of its part, for the run report: empty
     *         while a client drives it, or if one did when its part ended
     */
    Optional<String> unattended() {
        synchronized (lock) {
            Attached a = done ? attachedAtEnd : attached;
            if (a != null || lastLeft == null || failure != null) {
                return Optional.empty();
            }
            return Optional.of(lastLeft.describe());
        }
    }

    /** The effects of a client's commands on this robot. */
    private final class SessionEffects implements CommandHandler.Effects {
        private final PioneerSession session;
        private final IntConsumer simExit;
        private final OdometryFrame frame;

        SessionEffects(PioneerSession session, IntConsumer simExit, OdometryFrame frame) {
            this.session = session;
            this.simExit = simExit;
            this.frame = frame;
        }

        @Override
        public void request(Command c) {
            commands.add(c);
        }

        @Override
        public void reply(PioneerPacket p) {
            session.send(p);
        }

        @Override
        public void resetOdometry() {
            RobotState s = latest;
            if (s != null) {
                frame.resetAt(s.x(), s.y(), s.th());
            }
        }

        @Override
        public void resetToStart() {
            commands.add(new Command.ResetToStart());
        }

        @Override
        public void simStat(int mode) {
            if (mode != 0) {
                commands.add(new Command.ReportTruePose(true));
            }
            simStatMode = mode;
        }

        @Override
        public void close(String reason) {
            session.end(reason);
        }

        @Override
        public void simExit(int code) {
            if (options.allowSimExit()) {
                LOG.warning(() -> "robot " + served.name() + ": the ARIA client sent SIM_EXIT " + code + "; the run ends");
                simExit.accept(code);
            } else {
                LIMITED.warning("refused SIM_EXITs of robot " + served.name(), () -> "robot " + served.name()
                        + ": the ARIA client sent SIM_EXIT " + code + "; refused (env --allow-sim-exit lets a client"
                        + " end the run)");
            }
        }

        @Override
        public void log(String kind, Supplier<String> line) {
            LIMITED.info(kind, line);
        }
    }
}
