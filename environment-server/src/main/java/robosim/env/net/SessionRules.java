package robosim.env.net;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.logging.Logger;
import robosim.env.core.Simulation;
import robosim.env.world.RobotSpec;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.FrameException;
import robosim.protocol.MessageCodec;
import robosim.protocol.LinkHello;
import robosim.protocol.LinkRequests;
import robosim.protocol.LogLimiter;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotRequests;
import robosim.protocol.Snapshot;

/**
 * The protocol's rules for each peer, applied by the step loop: who may say what and when. A robot
 * says hello once, with a name the world knows and no other program is using, before the first
 * step or later ({@link RobotJoins}); then sends exactly one set of requests for each step the
 * Environment opens after it was welcomed. A shared link
 * (a connection that said {@link LinkHello}) follows the same rules for each of its robots, and a
 * robot that breaks one is dropped alone while the link goes on. A viewer says hello and then only
 * listens; a control client says hello and may then change the run. When the run has a secret
 * ({@link Access}), every hello must present it, except a viewer's when anyone may watch. Anything
 * else closes that peer, with a log line naming it and the rule. Lines that peers can repeat go
 * through one {@link LogLimiter} for the server, one line per kind a second.
 */
final class SessionRules implements RunSessions {
    private static final Logger LOG = Logger.getLogger(SessionRules.class.getName());
    /** The reason given when a peer ends its connection cleanly. */
    static final String DISCONNECTED = "it disconnected";
    /** Why a robot whose connection ended cleanly but without a bye is lost. */
    static final String NO_BYE = "the connection closed without a bye";

    private final CurrentRun run;
    private final Access access;
    private final RobotJoins joins;
    private final Map<String, Connection> robots = new LinkedHashMap<>();
    private final ViewerPortRules viewerPort;
    private final Set<String> waiting = new LinkedHashSet<>();
    private final Departures departures = new Departures();
    private final LogForwarding log = new LogForwarding();
    private final Refusals refusals = new Refusals();
    /** The limiter of the lines peers can repeat (refusals, refused requests), shared by the rules' parts. */
    private final LogLimiter limited = new LogLimiter(LOG);
    /** The last step each robot answered in time, for control clients' status. */
    private final Map<String, Long> answered = new HashMap<>();
    private long openStep;
    private Map<String, List<Command>> commands;

    /** Rules without a run secret, with the default caps. */
    SessionRules(Simulation sim) {
        this(sim, Access.open(), Limits.defaults());
    }

    SessionRules(Simulation sim, Access access, Limits limits) {
        this.run = new CurrentRun(sim);
        this.access = access;
        this.joins = new RobotJoins(run, access, limits, departures, refusals, limited);
        this.viewerPort = new ViewerPortRules(run, access, limits, limited);
    }

    /** @return the simulation run now (a restart or load replaces it) */
    Simulation sim() {
        return run.sim();
    }

    /**
     * Puts a new simulation in place of the one run now, between two steps: every robot of the run
     * is told why in a bye and taken out (a shared link stays open for its robots to say hello
     * again), and the new run waits for its robots as a run does at its start. Viewers and control
     * clients stay.
     *
     * @param next the new simulation
     * @param why  what the robots are told
     */
    void replace(Simulation next, String why) {
        for (String robot : List.copyOf(robots.keySet())) {
            endFor(robot, why);
        }
        run.replace(next);
        departures.reset();
        refusals.clear();
        answered.clear();
        openStep = 0;
        commands = null;
        waiting.clear();
        joins.takeWorldChanged();
    }

    /** @return the Environment's log lines for the control clients that follow them */
    @Override
    public LogForwarding log() {
        return log;
    }

    /**
     * Routes control clients' requests to run control; until then they are refused.
     *
     * @param control where they go
     */
    void routeControlTo(ControlRequests control) {
        viewerPort.routeControlTo(control);
    }

    /** @return the run, as a restart or a load replaces its simulation */
    CurrentRun run() {
        return run;
    }

    /** @return the limiter of the lines peers can repeat, for run control's */
    LogLimiter limited() {
        return limited;
    }

    /**
     * @return whether the run may start: every robot the world names is connected; in an open world,
     *         any one robot (the others may join later)
     */
    boolean allConnected() {
        return sim().world().rules().open() ? !robots.isEmpty() : missing().isEmpty();
    }

    /** @return the robots the world names that are not connected, in the world's order */
    List<String> missing() {
        List<String> m = new ArrayList<>();
        for (RobotSpec r : sim().world().robots()) {
            if (!robots.containsKey(r.name())) {
                m.add(r.name());
            }
        }
        return m;
    }

    int viewerCount() {
        return viewerPort.viewerCount();
    }

    @Override
    public Map<String, Connection> connectedRobots() {
        return robots;
    }

    /** @return the last step the robot answered in time, 0 if none */
    @Override
    public long lastAnswered(String robot) {
        return answered.getOrDefault(robot, 0L);
    }

    /** @return the robots refused since the run began to wait for its robots, with why, oldest first */
    Map<String, String> refusals() {
        return refusals.all();
    }

    /** @see RobotJoins#robotStep */
    long robotStep(String robot, long step) {
        return joins.robotStep(robot, step);
    }

    Set<String> waitingFor() {
        return waiting;
    }

    /** The run starts: from now robots that join or go are recorded. */
    void start() {
        departures.start();
    }

    /** @return the robots that left, were dropped or were lost since the run started, in that order */
    List<Departure> departures() {
        return departures.list();
    }

    /** @return whether a robot was added to the world since the last call (viewers must be sent the world again) */
    boolean takeWorldChanged() {
        return joins.takeWorldChanged();
    }

    /** @return the joins and departures since the last call, for the next snapshot */
    List<Snapshot.Event> takeEvents() {
        return departures.takeEvents();
    }

    /** @return the robots that joined after the run started, in that order */
    List<Join> joins() {
        return departures.joins();
    }

    /** Marks a robot gone at the step open (or the last step run). */
    private void departed(String robot, Departure.Kind kind, String reason) {
        departures.mark(robot, kind, openStep > 0 ? openStep : sim().stepCount(), reason);
    }

    /** Marks the robots of a robot connection lost. */
    private void lost(Connection c, String reason) {
        if (c.kind != Connection.Kind.ROBOT) {
            return;
        }
        if (c.isLink()) {
            for (String robot : c.robots()) {
                departed(robot, Departure.Kind.LOST, reason);
            }
        } else if (c.name() != null && robots.get(c.name()) == c) {
            departed(c.name(), Departure.Kind.LOST, reason);
        }
    }

    /** Opens a step: from now the connected robots' requests for it are collected. */
    void openStep(long step) {
        departures.start();
        openStep = step;
        commands = new HashMap<>();
        waiting.clear();
        waiting.addAll(robots.keySet());
    }

    /**
     * Closes the open step.
     *
     * @return the requests collected for it, by robot; a robot absent sent none in time
     */
    Map<String, List<Command>> closeStep() {
        Map<String, List<Command>> collected = commands;
        openStep = 0;
        commands = null;
        waiting.clear();
        return collected;
    }

    /** Sends a snapshot (or a world that changed) to every viewer, encoded once. */
    void broadcastSnapshot(Message snapshot, MessageCodec codec) {
        viewerPort.broadcast(snapshot, codec);
    }

    /** A peer sent a message. */
    void received(Connection from, Message m) {
        if (from.kind == Connection.Kind.ROBOT) {
            fromRobot(from, m);
        } else {
            viewerPort.received(from, m);
        }
    }

    private void fromRobot(Connection c, Message m) {
        if (c.isClosed()) {
            return;
        }
        if (c.isLink()) {
            fromLink(c, m);
        } else if (c.name() == null) {
            if (m instanceof RobotHello hello) {
                hello(c, hello);
            } else if (m instanceof LinkHello hello) {
                // an in-process link comes from this JVM: no other user can reach it, so it needs no secret
                String refusal = c.isInProcess() ? null : access.refusal("a shared link", hello.token());
                if (refusal != null) {
                    refusals.refused(Refusals.linkOf(printable(hello.client())), refusal);
                    c.refuse(refusal);
                    return;
                }
                c.becomeLink(hello.client());
                refusals.admitted(Refusals.linkOf(printable(hello.client())));
                LOG.fine(() -> "a shared link opened: " + c.peer());
            } else {
                c.close("expected robotHello or linkHello as its first message, got " + typeOf(m));
            }
        } else if (m instanceof RobotRequests req) {
            requests(c, c.name(), req.step(), req.commands());
        } else if (m instanceof Bye bye) {
            LOG.info(() -> "robot " + c.name() + " left at step " + sim().stepCount() + ": " + printable(bye.reason()));
            departed(c.name(), Departure.Kind.LEFT, reported(bye.reason()));
            c.shut();
            drop(c.name(), null);
        } else {
            c.close("sent " + typeOf(m) + " during step " + openStep + "; a robot sends only robotRequests");
        }
    }

    private void fromLink(Connection c, Message m) {
        if (m instanceof LinkRequests req) {
            for (LinkRequests.ForRobot r : req.robots()) {
                // a robot already dropped may still be in a frame the link sent before it learnt so
                if (c.carries(r.robot()) && robots.get(r.robot()) == c) {
                    requests(c, r.robot(), req.step(), r.commands());
                }
            }
        } else if (m instanceof RobotHello hello) {
            hello(c, hello);
        } else if (m instanceof Bye bye && bye.robot() != null) {
            if (c.carries(bye.robot()) && robots.get(bye.robot()) == c) {
                LOG.info(() -> "robot " + bye.robot() + " left at step " + sim().stepCount() + ": " + printable(bye.reason()));
                departed(bye.robot(), Departure.Kind.LEFT, reported(bye.reason()));
                drop(bye.robot(), null);
            }
        } else if (m instanceof Bye bye) {
            LOG.info(() -> c.peer() + " left at step " + sim().stepCount() + ": " + printable(bye.reason()));
            for (String robot : c.robots()) {
                departed(robot, Departure.Kind.LEFT, reported(bye.reason()));
                drop(robot, null);
            }
            c.shut();
        } else {
            closeLink(c, "sent " + typeOf(m) + " during step " + openStep
                    + "; a link sends only robotHello, linkRequests and bye");
        }
    }

    /** Closes a shared link, dropping each of its robots with a log line that names it. */
    private void closeLink(Connection c, String reason) {
        for (String robot : c.robots()) {
            drop(robot, "its link " + reason);
        }
        c.close(reason);
    }

    private void hello(Connection c, RobotHello hello) {
        joins.hello(c, hello, robots, openStep);
    }

    private void requests(Connection c, String name, long step, List<Command> sent) {
        if (step != openStep || !waiting.contains(name)) {
            String open = openStep == 0 ? "before step " + (sim().stepCount() + 1) + " was opened"
                    : waiting.contains(name) ? "while step " + openStep + " is open"
                    : "after it had already sent its requests for step " + openStep;
            String rule = "robot " + name + " sent requests for step " + step + " " + open;
            drop(name, rule);
            return;
        }
        commands.put(name, sent);
        waiting.remove(name);
        answered.put(name, step);
    }

    /**
     * A peer sent a frame holding a value that breaks a rule of its message (see
     * {@link robosim.protocol.InvalidValueException}). A robot is dropped, its log line naming the
     * step open; any other peer is closed.
     *
     * @param rule the rule's text
     */
    void invalid(Connection c, String rule) {
        String name = c.name();
        if (c.isLink()) {
            // the frame could not be read, so whose request it was is unknown: the link goes
            closeLink(c, "sent an invalid message: " + rule);
        } else if (c.kind == Connection.Kind.ROBOT && name != null && robots.get(name) == c) {
            String when = openStep == 0 ? "before step " + (sim().stepCount() + 1) + " was opened"
                    : "for step " + openStep;
            drop(name, "robot " + name + " sent an invalid request " + when + ": " + rule);
        } else {
            closed(c, "sent an invalid message: " + rule);
        }
    }

    /**
     * A peer's connection failed. A frame that breaks the rules drops the robots on it, told why as
     * far as the connection still carries it; any other failure (a reset, a stream that ends inside a
     * frame) has lost them.
     *
     * @param e what reading or writing threw
     */
    void failed(Connection c, IOException e) {
        if (!(e instanceof FrameException)) {
            lost(c, "the connection failed: " + e.getMessage());
            c.close(e.getMessage());
        }
        closed(c, e.getMessage());
    }

    /** A peer's connection ended, cleanly ({@link #DISCONNECTED}) or for the reason given. */
    void closed(Connection c, String reason) {
        if (DISCONNECTED.equals(reason)) {
            lost(c, NO_BYE);
            c.shut();
        }
        if (c.kind == Connection.Kind.VIEWER) {
            viewerPort.closed(c);
            if (!DISCONNECTED.equals(reason)) {
                c.close(reason);
            }
            return;
        }
        String name = c.name();
        if (c.isLink()) {
            for (String robot : c.robots()) {
                drop(robot, DISCONNECTED.equals(reason) ? null : "its link: " + reason);
                if (DISCONNECTED.equals(reason)) {
                    LOG.info(() -> "robot " + robot + " disconnected at step " + sim().stepCount() + " with its link");
                }
            }
            if (!DISCONNECTED.equals(reason)) {
                c.close(reason);
            }
        } else if (name != null && robots.get(name) == c) {
            drop(name, DISCONNECTED.equals(reason) ? null : reason);
            if (DISCONNECTED.equals(reason)) {
                LOG.info(() -> "robot " + name + " disconnected at step " + sim().stepCount());
            }
        } else if (!DISCONNECTED.equals(reason)) {
            c.close(reason);
        }
    }

    /**
     * Takes a robot out of the run: its connection is closed and its body stays where it stopped.
     * A robot dropped for a reason is told it in a bye, and marked dropped in the run report unless
     * it has already gone otherwise.
     *
     * @param reason logged with the robot's name, or null for an orderly leave
     */
    @Override
    public void drop(String name, String reason) {
        if (reason != null) {
            departed(name, Departure.Kind.DROPPED, reason);
        }
        Connection c = takeOut(name);
        if (c == null) {
            return;
        }
        if (c.isLink()) {
            c.dropRobot(name, reason);
        } else if (reason != null) {
            c.send(new Bye(reason));
            c.close(reason);
        } else {
            c.sendAndClose(new Bye(Bye.GOODBYE));
        }
    }

    /**
     * Takes out, as lost, the robots whose connection closed by itself since they were last served
     * (a write to it failed, or it fell too far behind), so that no step waits for a robot that can
     * no longer answer. Called once a step, after its states are sent.
     */
    void reapClosed() {
        for (Map.Entry<String, Connection> e : List.copyOf(robots.entrySet())) {
            if (e.getValue().isClosed()) {
                String robot = e.getKey();
                departed(robot, Departure.Kind.LOST, "its connection closed (the log says why)");
                takeOut(robot);
                LOG.info(() -> "robot " + robot + " lost at step " + sim().stepCount() + ": its connection closed");
            }
        }
    }

    /** Takes a robot out of the run's connected robots, its body halted. @return its connection, or null */
    private Connection takeOut(String name) {
        Connection c = robots.remove(name);
        waiting.remove(name);
        sim().halt(name);
        sim().setConnected(name, false);
        return c;
    }

    /**
     * Ends a robot's part because its run ends (a restart or load): it is told so with a
     * {@link Bye#DONE} bye, as at a run's end, not dropped.
     */
    private void endFor(String name, String why) {
        Connection c = takeOut(name);
        if (c == null) {
            return;
        }
        if (c.isLink()) {
            c.endRobot(name, Bye.DONE + why);
        } else {
            c.sendAndClose(new Bye(Bye.DONE + why));
        }
    }

    /** @return text a peer chose, escaped and cut for the run report (see {@link RobotHello#printable(String, int)}) */
    private static String reported(String text) {
        return RobotHello.printable(text, 300);
    }

    /** @return text a peer chose, as an escaped excerpt for one log line (see {@link LogLimiter#excerpt}) */
    static String printable(String text) {
        return LogLimiter.excerpt(text);
    }

    private static String typeOf(Message m) {
        return m.getClass().getSimpleName();
    }
}
