package robosim.env.net;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import robosim.env.core.RobotSummary;
import robosim.env.core.Simulation;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.MessageCodec;
import robosim.protocol.TimeStep;

/**
 * The Environment on the network: accepts robots and viewers, waits for every robot the world
 * names, then drives lockstep steps: it sends each robot its time step and state, waits (up to the
 * step deadline) for every robot's requests for that step, advances the {@link Simulation}, and
 * sends the new frame to the viewers. One thread, the step loop, changes all state; a peer that
 * breaks the protocol is closed with one log line and the run goes on for the others.
 */
public final class EnvironmentServer implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(EnvironmentServer.class.getName());
    private static final int MAX_QUEUED_ROBOT = 64;
    private static final int MAX_QUEUED_VIEWER = 100_000;

    private final Simulation sim;
    private final ServerOptions options;
    private final MessageCodec codec = new MessageCodec();
    private final BlockingQueue<ServerEvent> events = new LinkedBlockingQueue<>();
    private final List<Connection> all = new CopyOnWriteArrayList<>();
    private final SessionRules rules;
    private ServerSocket robotSocket;
    private ServerSocket viewerSocket;
    private volatile boolean closing;

    /**
     * @param sim     the simulation to drive
     * @param options how to run
     */
    public EnvironmentServer(Simulation sim, ServerOptions options) {
        this.sim = sim;
        this.options = options;
        this.rules = new SessionRules(sim);
    }

    /**
     * Opens both listening sockets.
     *
     * @throws IOException if a port cannot be bound
     */
    public void bind() throws IOException {
        InetAddress addr = InetAddress.getByName(options.bindAddress());
        robotSocket = new ServerSocket(options.robotPort(), 50, addr);
        viewerSocket = new ServerSocket(options.viewerPort(), 50, addr);
        accept(robotSocket, Connection.Kind.ROBOT);
        accept(viewerSocket, Connection.Kind.VIEWER);
    }

    /** @return the port robots connect to */
    public int robotPort() {
        return robotSocket.getLocalPort();
    }

    /** @return the port viewers connect to */
    public int viewerPort() {
        return viewerSocket.getLocalPort();
    }

    private void accept(ServerSocket server, Connection.Kind kind) {
        Thread t = new Thread(() -> {
            while (!closing) {
                try {
                    Socket s = server.accept();
                    int queued = kind == Connection.Kind.ROBOT ? MAX_QUEUED_ROBOT : MAX_QUEUED_VIEWER;
                    Connection c = new Connection(kind, s, events, codec, options.maxFrame(), queued);
                    all.add(c);
                    c.start();
                } catch (IOException e) {
                    if (!closing) {
                        LOG.warning("accepting " + kind.name().toLowerCase() + " connections failed: " + e.getMessage());
                    }
                    return;
                }
            }
        }, "env-accept-" + kind.name().toLowerCase());
        t.setDaemon(true);
        t.start();
    }

    /**
     * Waits for the world's robots, runs, and reports.
     *
     * @return how the run ended
     * @throws InterruptedException if interrupted
     * @throws IllegalStateException if the robots do not all connect in time
     */
    public RunReport run() throws InterruptedException {
        awaitRobots();
        LOG.info(() -> "all robots connected; running world " + sim.world().name());
        String reason = loop();
        for (Connection c : all) {
            c.sendAndClose(new Bye("done: " + reason));
        }
        for (Connection c : all) {
            c.awaitWritten(2000);
        }
        List<RobotSummary> summaries = new ArrayList<>();
        for (String name : sim.robotNames()) {
            summaries.add(sim.summary(name));
        }
        return new RunReport(sim.stepCount(), sim.timeMs(), reason, summaries);
    }

    private void awaitRobots() throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(options.connectTimeoutMs());
        while (!rules.allConnected() || rules.viewerCount() < options.waitViewers()) {
            long left = deadline - System.nanoTime();
            ServerEvent e = left > 0 ? events.poll(left, TimeUnit.NANOSECONDS) : null;
            if (e == null) {
                throw new IllegalStateException("robots " + rules.missing() + " and " + Math.max(0,
                        options.waitViewers() - rules.viewerCount()) + " viewer(s) did not connect within "
                        + options.connectTimeoutMs() + " ms");
            }
            rules.handle(e);
        }
    }

    private String loop() throws InterruptedException {
        long start = System.nanoTime();
        int stepMs = sim.world().stepMs();
        while (true) {
            if (rules.connectedRobots().isEmpty()) {
                return "every robot has disconnected";
            }
            if (options.maxSteps() > 0 && sim.stepCount() >= options.maxSteps()) {
                return "step limit " + options.maxSteps() + " reached";
            }
            long current = sim.stepCount() + 1;
            if (options.realtime()) {
                long due = start + TimeUnit.MILLISECONDS.toNanos((current - 1) * stepMs);
                long wait = due - System.nanoTime();
                if (wait > 0) {
                    TimeUnit.NANOSECONDS.sleep(wait);
                }
            }
            Map<String, List<Command>> commands = collect(current);
            sim.step(commands);
            rules.broadcastFrame(sim.frame());
        }
    }

    private Map<String, List<Command>> collect(long current) throws InterruptedException {
        Map<String, Connection> robots = new LinkedHashMap<>(rules.connectedRobots());
        for (Map.Entry<String, Connection> r : robots.entrySet()) {
            r.getValue().send(new TimeStep(current, sim.timeMs(), sim.state(r.getKey())));
        }
        Map<String, List<Command>> commands = new HashMap<>();
        rules.openStep(current, commands);
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(options.stepTimeoutMs());
        while (rules.waitingFor().size() > 0) {
            long left = deadline - System.nanoTime();
            ServerEvent e = left > 0 ? events.poll(left, TimeUnit.NANOSECONDS) : null;
            if (e == null) {
                Set<String> late = new LinkedHashSet<>(rules.waitingFor());
                for (String name : late) {
                    rules.drop(name, "it did not send its requests for step " + current + " within "
                            + options.stepTimeoutMs() + " ms");
                }
                break;
            }
            rules.handle(e);
        }
        rules.closeStep();
        return commands;
    }

    /** Stops listening and closes every connection. */
    @Override
    public void close() {
        closing = true;
        for (ServerSocket s : new ServerSocket[] {robotSocket, viewerSocket}) {
            if (s != null) {
                try {
                    s.close();
                } catch (IOException e) {
                    LOG.fine("closing listener: " + e.getMessage());
                }
            }
        }
        for (Connection c : all) {
            c.sendAndClose(new Bye("environment closing"));
        }
    }
}
