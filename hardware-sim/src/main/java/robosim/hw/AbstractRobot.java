package robosim.hw;

import com.fasterxml.jackson.core.JsonProcessingException;
import java.io.IOException;
import java.util.List;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.BiFunction;
import java.util.function.Function;
import java.util.function.Supplier;
import java.util.logging.Logger;
import robosim.protocol.LogLimiter;
import robosim.protocol.Command;
import robosim.protocol.Figure;
import robosim.protocol.MessageDelivery;
import robosim.protocol.RobotHello;
import robosim.protocol.RunSecret;
import robosim.protocol.SecretLookup;
import robosim.protocol.RobotState;
import robosim.protocol.Welcome;
import robosim.protocol.RobotParameters;

/**
 * What every Robot-Object shares, whatever its API (ARIA's Pioneer, the Nomadic Scout): its name,
 * its link to the Environment, the latest state the Environment reported, its request queue, and
 * waiting in simulated time.
 *
 * <p>The thread that connects, and every thread that waits with {@link #sleepSimulated}, is part of
 * the robot's code: each step the robot's requests are sent once all of them have yielded, which
 * keeps runs deterministic.
 *
 * <p>A robot uses a {@link RobotRuntime} with the other robots of its program: the default runtime,
 * unless it is given one with {@link #setRuntime} before it connects.
 */
public abstract class AbstractRobot {
    private static final Logger LOG = Logger.getLogger(AbstractRobot.class.getName());
    /** The Environment refuses a bad request each time it is sent: one line a second. */
    private final LogLimiter refusals = new LogLimiter(LOG);
    private static final InheritableThreadLocal<AbstractRobot> CURRENT = new InheritableThreadLocal<>();
    /** The robots a thread connected: the thread is the code of each (see {@link #sleepSimulated}). */
    private static final ThreadLocal<java.util.Set<AbstractRobot>> CONNECTED_BY = new ThreadLocal<>();

    /** Who the robot is and where it connects: fixed once it first connects ({@link #relocate}). */
    private volatile String name;
    private volatile String host;
    private volatile int port;
    private final String robotType;
    private volatile RobotParameters parameters;
    private volatile RobotState state = new RobotState(0, 0, 0, 0, 0, 0, 0, 0, 0, false, 0);
    private volatile int stepMs = 100;
    private volatile WelcomeFacts facts;
    private volatile HardwareSimulator hardware;
    /** The runtime given, or null for the default one. */
    private volatile RobotRuntime givenRuntime;
    /** The runtime the latest connection used, once it began. */
    private volatile RobotRuntime usedRuntime;
    private volatile String connectionError;
    /** How the last attempt to connect ended, while {@link #hardware} is null. */
    private volatile RunEnd lastEnd;
    private final Queue<RobotMessage> inbox = new ConcurrentLinkedQueue<>();
    private final Queue<String> requestErrors = new ConcurrentLinkedQueue<>();
    private final Object messageNumbers = new Object();
    private long lastMessageId;

    /**
     * @param name       the robot's name in the world
     * @param host       the Environment's host
     * @param port       the Environment's robot port
     * @param robotType  the robot's type, for example {@code pioneer}
     * @param parameters the robot's parameters, sent to the Environment
     */
    protected AbstractRobot(String name, String host, int port, String robotType, RobotParameters parameters) {
        if (port <= 0 || port > 65535) {
            throw new IllegalArgumentException(port + " was supplied for port: a port is 1 to 65535");
        }
        this.name = name;
        this.host = host;
        this.port = port;
        this.robotType = robotType;
        this.parameters = parameters;
        this.facts = WelcomeFacts.none(name);
    }

    /**
     * Renames the robot, and gives it the Environment to connect to and the parameters it sends,
     * before it connects: for ARIA's connector, which makes a robot first and connects it once the
     * command line has said where ({@code ArRobotConnector}).
     *
     * @param name       the robot's name in the world
     * @param host       the Environment's host
     * @param port       the Environment's robot port
     * @param parameters the robot's parameters
     * @throws IllegalStateException    if the robot is connected
     * @throws IllegalArgumentException if the port is not 1 to 65535
     */
    protected void relocate(String name, String host, int port, RobotParameters parameters) {
        if (isConnected()) {
            throw new IllegalStateException("robot " + this.name + " is connected: it is renamed or moved only before");
        }
        if (port <= 0 || port > 65535) {
            throw new IllegalArgumentException(port + " was supplied for port: a port is 1 to 65535");
        }
        this.name = name;
        this.host = host;
        this.port = port;
        this.parameters = parameters;
        this.facts = WelcomeFacts.none(name);
    }

    /**
     * The robot the calling thread belongs to: the one it (or the thread that started it) connected.
     *
     * @return the robot, or null for a thread outside any robot's code
     */
    public static AbstractRobot current() {
        return CURRENT.get();
    }

    /**
     * Gives the robot the runtime it is to share with other robots of its program, instead of the
     * default runtime. The robot begins to use it when it connects.
     *
     * @param runtime its runtime, or null for the default one
     * @throws IllegalStateException if the robot is connected
     */
    public void setRuntime(RobotRuntime runtime) {
        if (isConnected()) {
            throw new IllegalStateException("robot " + name + " is connected: give it a runtime before it connects");
        }
        this.givenRuntime = runtime;
    }

    /**
     * @return the runtime the robot uses: the one given to it, else the default runtime it used when
     *         it last connected; null when given none and it has not connected
     */
    public RobotRuntime getRuntime() {
        RobotRuntime given = givenRuntime;
        return given != null ? given : usedRuntime;
    }

    /**
     * Connects to the Environment and waits for its welcome; the calling thread becomes part of the
     * robot's code.
     *
     * @param options timeouts
     * @throws IOException if the connection fails or the Environment refuses the robot
     */
    protected void connect(HardwareOptions options) throws IOException {
        connectFinding(options, (runtime, o) -> EnvironmentLinks.to(runtime, host, port, o));
    }

    /**
     * Connects, finding the secret as {@link RunSecret#find} does, and tries again over a new link
     * while a refusal may clear ({@link RunSecret#mayClear}): a robot started with its Environment
     * may have looked before the Environment wrote its secret, or found the file an earlier run
     * left. Any other refusal, or the same secret refused again, ends the attempt at once. The
     * connect timeout bounds the whole.
     */
    private void connectFinding(HardwareOptions options,
                                BiFunction<RobotRuntime, HardwareOptions, EnvironmentLink> links) throws IOException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(options.connectTimeoutMs());
        // found now too, so that a secret that breaks its rule is said before any connection
        SecretLookup lookup = new SecretLookup(host, port, RunSecret.find(null, host, port));
        for (int tries = 1; ; tries++) {
            try {
                // a later attempt has what is left of the connect timeout, which bounds the whole
                long leftMs = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
                HardwareOptions attempt = tries == 1 ? options
                        : new HardwareOptions(Math.max(1, leftMs), options.lostAfterMs(), options.yieldWarningMs());
                connect(attempt, runtime -> links.apply(runtime, attempt), lookup.given(), lookup);
                return;
            } catch (RefusedException e) {
                // a shared link's refusal is of the secret the robot that opened the link presented
                String presented = e.byLink() ? e.linkSecret() : lookup.given();
                if (!lookup.clears(e.reason(), presented) || System.nanoTime() - deadline > 0) {
                    throw e;
                }
                LOG.info(() -> "robot " + name + ": the Environment at " + host + ":" + port + " refused the run secret"
                        + " found, and another has appeared since; trying again");
            }
        }
    }

    /**
     * Connects as {@link #connect(HardwareOptions)} does, presenting a secret the caller already
     * holds (a bridge inside the Environment's own process) instead of looking for one. It always
     * reaches the Environment itself, whatever Pioneer robot server its runtime names.
     *
     * @param options timeouts
     * @param secret  the run secret, or null when the run has none
     * @throws IOException if the connection fails or the Environment refuses the robot
     */
    protected void connectPresenting(HardwareOptions options, String secret) throws IOException {
        connect(options, runtime -> EnvironmentLinks.toEnvironment(runtime, host, port, options), secret, null);
    }

    /**
     * Connects over the given link, as {@link #connect(HardwareOptions)} does.
     *
     * @param options timeouts
     * @param link    how to reach the Environment
     * @throws IOException if the connection fails or the Environment refuses the robot
     */
    void connect(HardwareOptions options, EnvironmentLink link) throws IOException {
        EnvironmentLink[] first = {link};
        connectFinding(options, (runtime, o) -> {
            EnvironmentLink l = first[0];
            first[0] = null;
            return l != null ? l : EnvironmentLinks.to(runtime, host, port, o);
        });
    }

    /**
     * @param links  makes the robot's link, given the runtime it uses
     * @param lookup gives the secret once connected, or null to present {@code secret}
     */
    private void connect(HardwareOptions options, Function<RobotRuntime, EnvironmentLink> links, String secret,
                         Supplier<String> lookup) throws IOException {
        HardwareSimulator hw = new HardwareSimulator(new RobotHello(name, robotType, parameters, secret),
                this::responded, options, givenRuntime);
        if (lookup != null) {
            hw.lookUpSecret(lookup);
        }
        // the hardware may deliver the first step before connect returns; it waits for the first yield
        hardware = hw;
        Welcome w;
        try {
            w = hw.connect(links);
        } catch (IOException | RuntimeException e) {
            hardware = null;
            lastEnd = hw.runEnd();
            throw e;
        } finally {
            if (hw.runtime() != null) {
                usedRuntime = hw.runtime();
            }
        }
        stepMs = w.stepMs();
        facts = WelcomeFacts.of(name, w);
        state = w.state();
        welcomed(w.state());
        java.util.Set<AbstractRobot> mine = CONNECTED_BY.get();
        if (mine == null) {
            mine = new java.util.LinkedHashSet<>();
            CONNECTED_BY.set(mine);
        }
        mine.removeIf(r -> !r.isConnected());
        mine.add(this);
        CURRENT.set(this);
    }

    /**
     * Connects as {@link #connect} does, but records a failure instead of throwing it: the shared
     * part of each API's own connect call (ARIA's {@code blockingConnect}, the Nomad's
     * {@code connect_robot}).
     *
     * @param options timeouts
     * @return true if connected; otherwise {@link #getConnectionError()} says why
     */
    protected boolean tryConnect(HardwareOptions options) {
        try {
            connect(options);
            return true;
        } catch (IOException | RuntimeException e) {
            String reason = e.getMessage();
            connectionError = reason;
            LOG.warning(() -> "robot " + name + " could not connect: " + reason);
            return false;
        }
    }

    /**
     * Called once when the Environment has welcomed the robot, before the first step.
     *
     * @param initial the robot's state before the first step
     */
    protected void welcomed(RobotState initial) {
    }

    /**
     * Called on the hardware thread as each step's response arrives, while the robot's code is
     * yielded: records the new state. Subclasses that update more call this first.
     *
     * @param response the step's response
     */
    protected void responded(RobotSensorResponse response) {
        state = response.state();
        clock().stateArrived(response.state().timeMs());
        for (MessageDelivery m : response.state().messages()) {
            inbox.add(new RobotMessage(m));
        }
        for (String e : response.state().errors()) {
            refusals.warning("requests the Environment refused", () -> "robot " + name
                    + ": the Environment refused a request: " + RobotHello.printable(e, 200));
            requestErrors.add(e);
        }
    }

    // ---- messaging ----

    /**
     * Sends a message to one robot, delivered at a step boundary (see the world's comms settings).
     *
     * @param robot   the recipient's name
     * @param payload a string, or an object Jackson can write as JSON
     * @return the message's number, named in any error about it
     * @throws IllegalArgumentException if no robot is named
     */
    public long send(String robot, Object payload) {
        return message(Command.Addressing.ROBOT, robot, payload);
    }

    /**
     * Sends a message to the members of a group (not to this robot).
     *
     * @param group   the group
     * @param payload a string, or an object Jackson can write as JSON
     * @return the message's number
     * @throws IllegalArgumentException if no group is named
     */
    public long multicast(String group, Object payload) {
        return message(Command.Addressing.GROUP, group, payload);
    }

    /**
     * Sends a message to every other robot.
     *
     * @param payload a string, or an object Jackson can write as JSON
     * @return the message's number
     */
    public long broadcast(Object payload) {
        return message(Command.Addressing.ALL, null, payload);
    }

    private long message(Command.Addressing mode, String to, Object payload) {
        String kind;
        String body;
        if (payload instanceof String text) {
            kind = RobotMessage.TEXT;
            body = text;
        } else {
            kind = payload.getClass().getName();
            try {
                body = RobotMessage.JSON.writeValueAsString(payload);
            } catch (JsonProcessingException e) {
                throw new IllegalArgumentException("a " + kind + " cannot be sent: Jackson cannot write it: "
                        + e.getOriginalMessage(), e);
            }
        }
        // a message that breaks a rule throws before it takes a number, so the numbers stay dense
        synchronized (messageNumbers) {
            Command.SendMessage m = new Command.SendMessage(lastMessageId + 1, mode, to, kind, body);
            lastMessageId = m.id();
            request(m);
            return m.id();
        }
    }

    /**
     * Says something: viewers show it, recordings keep it, the Environment logs it.
     *
     * @param text at most 1000 characters
     * @throws IllegalArgumentException if it is null or longer
     */
    public void say(String text) {
        request(new Command.Say(text));
    }

    /**
     * Draws into the world's views, as a robot of ARIA's shows drawings in MobileEyes: the figures
     * replace whatever the layer showed, and viewers that show drawings ({@code --drawings}) draw them
     * translucent under the robots, in the robot's colour unless a figure names its own, until the
     * robot draws the layer again, clears it, or leaves. The Environment keeps at most
     * {@value Command.Draw#MAX_LAYERS} layers per robot, and a bounded number of coordinates in all
     * the robots' layers together: a layer past either is refused with an error the robot reads in
     * its next state, and the robot goes on.
     *
     * <p>Viewers are sent a layer each time it is drawn, so draw every so often (when what it shows
     * has changed), not every step.
     *
     * @param layer   the layer's name, 1 to 32 letters, digits, {@code .}, {@code _} or {@code -},
     *                such as {@code map} or {@code frontier}
     * @param figures what it shows now, at most {@value Command.Draw#MAX_FIGURES} figures and
     *                {@value Figure#MAX_NUMBERS} numbers in all; empty clears the layer
     * @throws IllegalArgumentException if the layer's name or the figures break those rules
     */
    public void draw(String layer, List<Figure> figures) {
        request(new Command.Draw(layer, figures));
    }

    /**
     * Clears one layer of the robot's drawings; a layer it has not drawn is left as it is.
     *
     * @param layer the layer's name
     * @throws IllegalArgumentException if the name breaks {@link #draw}'s rule
     */
    public void clearDrawing(String layer) {
        request(new Command.Draw(layer, List.of()));
    }

    /**
     * Reports a find of one of the world's objects (GoldFinder's {@code gold}); the Environment
     * checks it against the object's true position and refuses a report from too far away.
     *
     * @param object what was found
     * @throws IllegalArgumentException if it is null or blank
     */
    public void reportFound(String object) {
        request(new Command.ReportFound(object));
    }

    /**
     * Reports one of the robot's figures for the run's results, such as the cells it has explored or
     * the step it reached its goal: the Environment keeps the last value of each name for the run's
     * report (an experiment's table takes it from there), and recordings and viewers see each report.
     * Report a figure when it changes, or once at the end; reporting it every step costs a little on
     * the wire and nothing else.
     *
     * <p>The report goes with the robot's next requests, as every command does, so the run is the
     * same at any speed. The Environment keeps at most {@value Command.ReportMetric#MAX_METRICS} names
     * per robot: a new name past them is not kept, and the robot reads why in its next state
     * ({@link #pollRequestError()}). A robot that is not connected sends nothing.
     *
     * @param name  the figure's name: a letter, then up to 63 letters, digits, {@code _}, {@code .} or
     *              {@code -}, such as {@code cellsExplored}
     * @param value its value now
     * @throws IllegalArgumentException if the name breaks that rule or the value is not finite, saying
     *                                  which
     */
    public void reportMetric(String name, double value) {
        request(new Command.ReportMetric(name, value));
    }

    /**
     * Asks the Environment to end the run, as a program does that has found what it looked for or
     * knows the run has nothing more to show. The run ends after the step the request goes with (the
     * robot's next requests, as every command); every robot's part then ends with the run's end
     * ({@link RunEnd.Kind#RUN_ENDED}), and the run's report names this robot, the step and the reason.
     * Only the first request of a run counts, whichever robot made it.
     *
     * <p>Keep the robot in the run until then: wait for the end (ARIA's {@code waitForRunExit}, or a
     * sleep in simulated time) rather than disconnect or return from {@code main} at once, which
     * would leave without sending the request.
     *
     * @param reason why, for the run's report and log, such as {@code gold found}: 1 to
     *               {@value Command.EndRun#MAX_REASON} characters, one line (no control characters)
     * @throws IllegalArgumentException if the reason breaks that rule, saying how
     */
    public void endRun(String reason) {
        request(new Command.EndRun(reason));
    }

    /**
     * @param group a group whose multicasts this robot will receive
     * @throws IllegalArgumentException if it is null or blank
     */
    public void joinGroup(String group) {
        request(new Command.JoinGroup(group));
    }

    /**
     * @param group a group to leave
     * @throws IllegalArgumentException if it is null or blank
     */
    public void leaveGroup(String group) {
        request(new Command.LeaveGroup(group));
    }

    /** @return the next message received, or null if none is waiting */
    public RobotMessage poll() {
        return inbox.poll();
    }

    /**
     * Waits in simulated time (yielding) for the next message.
     *
     * @param timeoutMs the longest simulated wait, ms
     * @return the message, or null if none came in time or the robot was disconnected
     */
    public RobotMessage receive(long timeoutMs) {
        RobotMessage m = inbox.poll();
        if (m != null || !isConnected()) {
            return m;
        }
        HardwareSimulator hw = hardware;
        long deadline = hw.timeMs() + Math.max(timeoutMs, 1);
        try {
            hw.await(t -> !inbox.isEmpty() || t >= deadline);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return inbox.poll();
    }

    /**
     * @return the next of the Environment's complaints about this robot's requests (an unknown
     *         recipient, a message over the size limit, ...), or null
     */
    public String pollRequestError() {
        return requestErrors.poll();
    }

    /** @return why the last connection attempt failed, or null */
    public String getConnectionError() {
        return connectionError;
    }

    /**
     * Leaves the run.
     *
     * @return true if the robot was connected and has now left; false if it was not connected (as
     *         ARIA's {@code ArRobot::disconnect} answers)
     */
    public boolean disconnect() {
        HardwareSimulator hw = hardware;
        if (hw != null && !hw.isEnded()) {
            hw.disconnect("the robot's program disconnected");
            return true;
        }
        return false;
    }

    /**
     * How the robot's part in the run ended: the Environment ended the run, the program left, the
     * Environment refused or dropped the robot, or it was lost (it closed the connection without a
     * bye, the connection broke, or it sent nothing, neither a step nor a keep-alive, for the lost
     * time: 10 s unless the system property {@value HardwareOptions#LOST_AFTER_PROPERTY} says
     * otherwise). {@link RunEnd#describe()} says it in one line.
     *
     * @return the end, or null while the robot is connected (or before it tried to connect)
     */
    public RunEnd getRunEnd() {
        HardwareSimulator hw = hardware;
        return hw == null ? lastEnd : hw.runEnd();
    }

    /** @return whether the robot is connected to the Environment */
    public boolean isConnected() {
        HardwareSimulator hw = hardware;
        return hw != null && !hw.isEnded();
    }

    /**
     * Queues a motion command for the current step.
     *
     * @param command the command
     */
    protected void request(Command command) {
        HardwareSimulator hw = hardware;
        if (hw != null) {
            hw.request(new RobotRequest(command));
        }
    }

    /**
     * Yields the calling thread for {@code ms} of simulated time, at least one step.
     *
     * @param ms simulated milliseconds
     */
    public void sleepSimulated(long ms) {
        HardwareSimulator hw = hardware;
        if (hw == null || hw.isEnded()) {
            return;
        }
        long wake = hw.timeMs() + Math.max(ms, 1);
        java.util.Set<AbstractRobot> mine = CONNECTED_BY.get();
        java.util.List<HardwareSimulator> parked = java.util.List.of();
        if (mine != null && mine.size() > 1) {
            parked = new java.util.ArrayList<>();
            // the thread is the code of other robots too: they go on while it sleeps on this one
            for (AbstractRobot other : mine) {
                HardwareSimulator o = other.hardware;
                if (other != this && o != null && !o.isEnded()) {
                    long otherWake = o.timeMs() + Math.max(ms, 1);
                    o.park(t -> t >= otherWake);
                    parked.add(o);
                }
            }
        }
        try {
            hw.await(t -> t >= wake);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            parked.forEach(HardwareSimulator::unpark);
        }
    }

    /**
     * Keeps the robot in the run after every thread of its code has ended (for programs whose work
     * is done by per-cycle tasks): the JVM then stays up until the robot is disconnected.
     *
     * @param keep whether to keep it
     */
    protected void keepAlive(boolean keep) {
        hardware.keepAlive(keep);
    }

    /** @return the latest state the Environment reported */
    protected RobotState state() {
        return state;
    }

    /** @return the robot's name */
    public String getName() {
        return name;
    }

    /** @return the robot's parameters */
    public RobotParameters getParameters() {
        return parameters;
    }

    /** @return the step length, simulated ms */
    public int getStepMs() {
        return stepMs;
    }

    /**
     * The name the robot's server gives it: a Pioneer robot server's name for its robot (from its
     * handshake, as ARIA's {@code getRobotName} reads it), once connected through one; otherwise,
     * in the Environment, the robot's own name.
     *
     * @return the name
     */
    public String getServerRobotName() {
        HardwareSimulator hw = hardware;
        String server = hw == null ? null : hw.serverRobotName();
        return server != null ? server : name;
    }

    /**
     * One of the world's properties (its world file's {@code <property>} elements), as the
     * Environment's welcome gave them: what a program needs to know of the world, such as a maze's
     * cell size. Valid once the robot is connected; before, and on a Pioneer port, there are none.
     *
     * @param name the property's name
     * @return its value, or null when the world does not give it
     */
    public String getWorldProperty(String name) {
        return facts.properties().get(name);
    }

    /**
     * One of the world's properties as a number (see {@link #getWorldProperty(String)}).
     *
     * @param name     the property's name
     * @param fallback the value when the world does not give the property
     * @return its value, or {@code fallback}
     * @throws IllegalStateException naming the robot, the property and its value, if the world gives
     *                               the property but not as a finite decimal number
     */
    public double getWorldProperty(String name, double fallback) {
        return facts.number(name).orElse(fallback);
    }

    /**
     * One of the world's properties as a number, when the program has no sensible default.
     *
     * @param name the property's name
     * @return its value, or empty when the world does not give it
     * @throws IllegalStateException naming the robot, the property and its value, if the world gives
     *                               the property but not as a finite decimal number
     */
    public OptionalDouble getWorldNumber(String name) {
        return facts.number(name);
    }

    /**
     * @return all of the world's properties, name to value in the world file's order, unmodifiable
     *         (none before the robot is connected)
     */
    public Map<String, String> getWorldProperties() {
        return facts.properties();
    }

    /**
     * The run's seed, as the Environment's welcome gave it, so that a program's own random choices
     * (tie-breaks, say) follow it and the same seed gives the same run. Valid once the robot is
     * connected; before, and on a Pioneer port, it is 0.
     *
     * @return the run's seed
     */
    public long getRunSeed() {
        return facts.seed();
    }

    /** @return the runtime whose clock the robot's states set: its own, else the default one */
    private RobotRuntime clock() {
        RobotRuntime runtime = getRuntime();
        return runtime != null ? runtime : RobotRuntime.defaultRuntime();
    }

    /** @return simulated time of the latest state, ms */
    public long getSimTimeMs() {
        HardwareSimulator hw = hardware;
        return hw == null ? 0 : hw.timeMs();
    }

    /** @return the step of the latest state */
    public long getStep() {
        HardwareSimulator hw = hardware;
        return hw == null ? 0 : hw.step();
    }

    /** @return the Environment's host */
    public String getHost() {
        return host;
    }

    /** @return the Environment's robot port */
    public int getPort() {
        return port;
    }
}
