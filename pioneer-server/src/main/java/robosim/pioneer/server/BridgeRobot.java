package robosim.pioneer.server;

import java.io.IOException;
import java.util.Queue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.logging.Logger;
import robosim.hw.AbstractRobot;
import robosim.hw.HardwareOptions;
import robosim.pioneer.LaserPacket;
import robosim.pioneer.PioneerPacket;
import robosim.pioneer.SimStat;
import robosim.protocol.Command;
import robosim.protocol.RobotState;

/**
 * A world robot driven by an ARIA client: an ordinary robot client of the Environment, with its own
 * HardwareSimulator, whose program is the client's commands. Each step it sends what the client
 * asked since the last one, yields, and answers with a status packet (and the laser's packets, and
 * SIMSTAT when asked). While a client is attached, each step waits until its time has come in real
 * time, since ARIA keeps wall-clock time; with none attached the robot stands still and does not
 * hold the run back. It stays in the run between clients; each new client finds the odometry at
 * (0, 0, 0), as on a Pioneer that was just switched on.
 */
final class BridgeRobot extends AbstractRobot {
    private static final Logger LOG = Logger.getLogger(BridgeRobot.class.getName());

    private final ServedRobot served;
    private final PioneerPortOptions options;
    private final Queue<Command> commands = new ConcurrentLinkedQueue<>();
    private final CompletableFuture<Void> connected = new CompletableFuture<>();
    private volatile Attached attached;
    private volatile boolean frameResetDue;
    private volatile boolean cancelled;
    private volatile boolean resetAfterStep;
    private volatile int simStatMode;
    private volatile RobotState latest;
    /** Whether the world has a program find the motors enabled as it connects ({@code <world motors=...>}). */
    private volatile boolean motorsAtConnect;
    private long nextStepNanos;

    /** A client with its session and the robot's server state for it. */
    private record Attached(PioneerSession session, CommandHandler handler, SipBuilder sips, LaserScan laser,
                            OdometryFrame frame) {
    }

    BridgeRobot(ServedRobot served, String host, int port, PioneerPortOptions options) {
        super(served.name(), host, port, served.robotType(), served.parameters());
        this.served = served;
        this.options = options;
    }

    /**
     * Connects to the Environment on a thread of its own, which then runs the robot's steps.
     *
     * @param secret the run secret, or null
     * @return done when the Environment has welcomed the robot, or failed with why not
     */
    CompletableFuture<Void> start(String secret) {
        Thread t = new Thread(() -> run(secret), "pioneer-bridge-" + served.name());
        t.setDaemon(true);
        t.start();
        return connected;
    }

    /** The port no longer waits for this robot's welcome: it leaves the run as soon as it has joined. */
    void cancel() {
        cancelled = true;
        disconnect();
    }

    private void run(String secret) {
        try {
            connectPresenting(options.hardware(), secret);
        } catch (IOException | RuntimeException e) {
            connected.completeExceptionally(e);
            return;
        }
        if (cancelled) {
            // the port stopped waiting for the welcome: the robot must not stay in the run unserved
            disconnect();
            connected.completeExceptionally(new IOException("cancelled"));
            return;
        }
        latest = state();
        motorsAtConnect = Boolean.TRUE.equals(latest.motorsEnabled());
        connected.complete(null);
        while (isConnected()) {
            Attached a = attached;
            if (frameResetDue && a != null) {
                frameResetDue = false;
                RobotState before = latest;
                a.frame().resetAt(before.x(), before.y(), before.th());
            }
            pace(a);
            watchdog(a);
            boolean reset = false;
            Command c;
            while ((c = commands.poll()) != null) {
                reset |= c instanceof Command.ResetToStart;
                request(c);
            }
            sleepSimulated(getStepMs());
            RobotState s = state();
            latest = s;
            if (reset && a != null) {
                a.frame().resetAt(s.x(), s.y(), s.th());
            }
            if (a != null && a == attached && a.session().isOpen()) {
                report(a, s);
            }
        }
        Attached a = attached;
        if (a != null) {
            a.session().end("the robot left the run: " + (getRunEnd() == null ? "?" : getRunEnd().describe()));
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
        for (LaserPacket p : a.laser().packets(s.laser())) {
            session.send(p.toPacket());
        }
        int mode = simStatMode;
        double[] t = s.truePose();
        if (mode != 0 && t != null) {
            session.send(new SimStat(0, getStepMs(), options.realTime() ? getStepMs() : 0, getStepMs(),
                    (int) Math.round(t[0]), (int) Math.round(t[1]), 0, (int) Math.round(t[2])).toPacket());
            if (mode == 1) {
                simStatMode = 0;
            }
        }
    }

    /**
     * Attaches a client that has just connected: the odometry starts again at (0, 0, 0), the motors
     * are as the world has a program find them (disabled unless {@code <world motors="enabled">}, until
     * the client's ENABLE 1), the sonar is on and the laser off, as on a Pioneer just connected to.
     *
     * @param session the client's session
     * @param simExit what SIM_EXIT does when it is allowed
     */
    void attach(PioneerSession session, java.util.function.IntConsumer simExit) {
        OdometryFrame frame = new OdometryFrame();
        RobotState s = latest;
        if (s != null) {
            frame.resetAt(s.x(), s.y(), s.th());
        }
        LaserScan laser = new LaserScan();
        CommandHandler handler = new CommandHandler(served.name(), served.parameters(), served.factors(), laser, frame,
                new SessionEffects(session, simExit));
        Attached a = new Attached(session, handler, new SipBuilder(served.factors()), laser, frame);
        commands.add(new Command.Stop());
        commands.add(new Command.SetMotors(motorsAtConnect));
        commands.add(new Command.SetSonar(true));
        commands.add(laser.command(served.parameters().laserMaxRange()));
        simStatMode = 0;
        frameResetDue = true;
        attached = a;
        session.attach(handler, () -> handler.config(served.name(), getStepMs(), (int) options.watchdogMs()),
                () -> detach(a));
    }

    private void detach(Attached a) {
        if (attached == a) {
            attached = null;
            commands.add(new Command.Stop());
        }
    }

    /** The effects of a client's commands on this robot. */
    private final class SessionEffects implements CommandHandler.Effects {
        private final PioneerSession session;
        private final java.util.function.IntConsumer simExit;

        SessionEffects(PioneerSession session, java.util.function.IntConsumer simExit) {
            this.session = session;
            this.simExit = simExit;
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
            frameResetDue = true;
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
                LOG.warning(() -> "robot " + served.name() + ": the ARIA client sent SIM_EXIT " + code
                        + "; refused (env --allow-sim-exit lets a client end the run)");
            }
        }

        @Override
        public void log(String line) {
            LOG.info(line);
        }
    }
}
