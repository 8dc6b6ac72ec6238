package robosim.hw;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.LongPredicate;
import java.util.function.Supplier;
import java.util.logging.Logger;
import robosim.protocol.RobotHello;
import robosim.protocol.Welcome;

/**
 * A robot's hardware: between the robot's code and the Environment. It owns the robot's
 * {@code robotRequestQueue} and the {@link StepGate} where the robot's code yields, and it reaches
 * the Environment through an {@link EnvironmentLink}. The robot's code requests commands through
 * {@link RequestQueue}; the link delivers each step through {@link StepReceiver}, and the
 * simulator hands the step's {@link RobotSensorResponse} to the robot once its code has yielded.
 * Once the code has yielded again, the queue is drained and sent as the robot's requests for the
 * step, by the last robot thread to yield, so no thread wakes just to send. The watchdog of the
 * robot's {@link RobotRuntime} sends for robots whose code ended without yielding, warns about code
 * that does not yield, and sends what shared links have collected when some of their robots are
 * late. The robot uses its runtime from the moment it begins to connect until its part ends.
 */
public final class HardwareSimulator implements RequestQueue, StepReceiver {
    private static final Logger LOG = Logger.getLogger(HardwareSimulator.class.getName());
    /** How often the watchdog looks after each robot, ms. */
    static final long WATCH_MS = 50;

    private final RobotHello hello;
    /** The runtime the robot was given, or null for the default one. */
    private final RobotRuntime given;
    /** The runtime it uses, from the moment it begins to connect. */
    private volatile RobotRuntime runtime;
    private final AtomicBoolean leftRuntime = new AtomicBoolean();
    private final StepGate gate = new StepGate();
    private final Consumer<RobotSensorResponse> responses;
    private final Queue<RobotRequest> robotRequestQueue = new ConcurrentLinkedQueue<>();
    private final HardwareOptions options;
    private volatile EnvironmentLink link;
    private volatile RunEnd runEnd;
    private volatile long openStep;
    private volatile Thread keeper;
    private volatile long joinedNanos;
    private volatile boolean welcomed;
    /** Gives the secret to present once connected; null to present the hello's own. */
    private volatile Supplier<String> secret;
    /** The steps the run had run when the Environment welcomed the robot (written before {@link #welcomed}). */
    private volatile long welcomedAfterStep;
    private long warnedStep = -1;

    /**
     * @param hello     the robot's name, type and parameters
     * @param responses receives each step's response while the robot's code is yielded (the robot's
     *                  side of "receive a step")
     * @param options   timeouts
     */
    public HardwareSimulator(RobotHello hello, Consumer<RobotSensorResponse> responses, HardwareOptions options) {
        this(hello, responses, options, null);
    }

    /**
     * @param hello     the robot's name, type and parameters
     * @param responses receives each step's response while the robot's code is yielded
     * @param options   timeouts
     * @param runtime   the runtime the robot uses, or null for the default one
     */
    public HardwareSimulator(RobotHello hello, Consumer<RobotSensorResponse> responses, HardwareOptions options,
                             RobotRuntime runtime) {
        this.hello = hello;
        this.responses = responses;
        this.options = options;
        this.given = runtime;
    }

    /**
     * Connects over the link its {@link RobotRuntime} chooses (see {@link EnvironmentLinks}), says
     * hello and waits (bounded) for the Environment's welcome. The calling thread becomes part of the
     * robot's code.
     *
     * @param host the Environment's host
     * @param port its robot port
     * @return the welcome, with the robot's state before the first step
     * @throws IOException if the connection fails or the Environment refuses the robot
     */
    public Welcome connect(String host, int port) throws IOException {
        return connect(rt -> EnvironmentLinks.to(rt, host, port, options));
    }

    /**
     * Connects over the given link, as {@link #connect(String, int)} does.
     *
     * @param link how to reach the Environment; used for this robot alone
     * @return the welcome
     * @throws IOException if the connection fails or the Environment refuses the robot
     */
    public Welcome connect(EnvironmentLink link) throws IOException {
        return connect(rt -> link);
    }

    /**
     * Begins to use the robot's runtime, then connects over the link {@code links} makes for it.
     *
     * @param links the robot's link, given the runtime it uses
     * @return the welcome
     * @throws IOException if the connection fails or the Environment refuses the robot
     */
    Welcome connect(Function<RobotRuntime, EnvironmentLink> links) throws IOException {
        RobotRuntime rt = RobotRuntime.enter(given);
        runtime = rt;
        EnvironmentLink link;
        try {
            link = links.apply(rt);
        } catch (RuntimeException e) {
            leaveRuntime();
            throw e;
        }
        return open(link);
    }

    /** @return the name the robot's own server gives it (see {@link EnvironmentLink#serverRobotName()}), or null */
    String serverRobotName() {
        EnvironmentLink l = link;
        return l == null ? null : l.serverRobotName();
    }

    /** @return the runtime the robot uses, once it has begun to connect; else null */
    RobotRuntime runtime() {
        return runtime;
    }

    private Welcome open(EnvironmentLink link) throws IOException {
        Thread me = Thread.currentThread();
        // joined first: a step that comes before the welcome returns waits for this thread's yield
        gate.join(me);
        this.link = link;
        joinedNanos = System.nanoTime();
        runtime.runEndWatches().joining(this);
        try {
            Welcome w = link.open(hello, secret, this);
            welcomedAfterStep = w.state().step();
            welcomed = true;
            runtime.watch(this);
            if (gate.isClosed()) {
                runtime.unwatch(this); // it ended as it was welcomed
            }
            return w;
        } catch (IOException | RuntimeException e) {
            gate.leave(me);
            if (e instanceof RefusedException refused) {
                end(RunEnd.Kind.REFUSED, refused.reason());
            } else {
                end(RunEnd.Kind.NOT_CONNECTED, String.valueOf(e.getMessage()));
            }
            throw e;
        }
    }

    /**
     * Has the secret looked up once the connection is open, instead of the hello's own.
     *
     * @param lookup gives the secret to present
     */
    void lookUpSecret(Supplier<String> lookup) {
        this.secret = lookup;
    }

    @Override
    public void request(RobotRequest request) {
        robotRequestQueue.add(request);
    }

    /**
     * Yields the calling thread (making it part of the robot's code) until {@code wakeWhen} holds
     * for the simulated time, or the link ends. If it is the last of the code's threads to yield for
     * the open step, it sends the step's requests first.
     *
     * @param wakeWhen a condition on simulated time in ms, checked as each step arrives
     * @throws InterruptedException if interrupted while waiting
     */
    public void await(LongPredicate wakeWhen) throws InterruptedException {
        if (gate.yieldUntil(wakeWhen)) {
            sendRequests();
        }
        gate.awaitWake();
    }

    /**
     * Yields the calling thread while it waits on another robot: a thread that is the code of
     * several robots (one program driving two, as ARIA's twoRobotWander does) lets each of their
     * steps go on while it sleeps on one, up to the same wake, so that robots of one Environment
     * wake at the same step as the one it sleeps on and the run stays the same. It sends the step's
     * requests if it was the last to yield.
     *
     * @param wakeWhen the condition on this robot's simulated time it yields until
     */
    void park(LongPredicate wakeWhen) {
        if (gate.yieldUntil(wakeWhen)) {
            sendRequests();
        }
    }

    /** Ends {@link #park()}: the calling thread runs as this robot's code again. */
    void unpark() {
        gate.stopWaiting();
    }

    /** @return simulated time of the latest state, ms */
    public long timeMs() {
        return gate.timeMs();
    }

    /** @return the latest step whose state has arrived */
    public long step() {
        return gate.step();
    }

    /** @return whether the link has ended (or never opened) */
    public boolean isEnded() {
        return gate.isClosed();
    }

    /**
     * Keeps the robot connected, and the JVM up, after every thread of its code has ended, until
     * the connection ends.
     *
     * @param keep whether to keep it
     */
    public synchronized void keepAlive(boolean keep) {
        if (keep && keeper == null) {
            Thread t = new Thread(() -> {
                try {
                    gate.awaitClosed();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "hw-keep-" + hello.name());
            keeper = t;
            t.start();
        } else if (!keep && keeper != null) {
            keeper.interrupt();
            keeper = null;
        }
    }

    /**
     * @return how the robot's part in the run ended (the run's end, its own leave, a refusal, a drop,
     *         the Environment lost), or null while it lasts
     */
    public RunEnd runEnd() {
        return runEnd;
    }

    /** @return why the robot's part in the run ended (the reason of {@link #runEnd()}), or null while it lasts */
    public String endReason() {
        RunEnd e = runEnd;
        return e == null ? null : e.reason();
    }

    /**
     * Leaves the run: says bye and closes.
     *
     * @param reason for the Environment's log
     */
    public void disconnect(String reason) {
        leave(reason);
    }

    /** Says bye over the link and ends, with the end settled before the link's thread sees it close. */
    private void leave(String reason) {
        settle(RunEnd.Kind.LEFT, reason);
        EnvironmentLink l = link;
        if (l != null) {
            l.bye(reason);
        }
        close();
    }

    /**
     * @return where the robot is before its first step, for a {@link RunEndWatch}: null once a step
     *         has come, or once its part has ended
     */
    RunEndWatch.BeforeFirstStep beforeFirstStep() {
        EnvironmentLink l = link;
        if (openStep > 0 || runEnd != null || l == null) {
            return null;
        }
        return new RunEndWatch.BeforeFirstStep(hello.name(), l.environment(), welcomed,
                System.nanoTime() - joinedNanos, welcomed ? welcomedAfterStep : -1);
    }

    @Override
    public void step(RobotSensorResponse response) {
        openStep = response.openStep();
        if (gate.advance(response.step(), response.timeMs(), () -> responses.accept(response))) {
            sendRequests();
        }
    }

    @Override
    public void ended(RunEnd.Kind kind, String reason) {
        end(kind, reason);
    }

    /**
     * Sends the open step's requests: everything the robot's code queued before it yielded. Run by
     * whichever thread saw the robot's code yield (see {@link StepGate}); if the code has ended,
     * says bye instead.
     */
    private void sendRequests() {
        EnvironmentLink l = link;
        if (gate.participantCount() == 0 && keeper == null) {
            leave("the robot's code has ended");
            return;
        }
        List<RobotRequest> requests = new ArrayList<>();
        RobotRequest req;
        while ((req = robotRequestQueue.poll()) != null) {
            requests.add(req);
        }
        try {
            l.send(openStep, requests);
        } catch (IOException e) {
            end(RunEnd.Kind.LOST, "sending requests failed: " + e.getMessage());
        }
    }

    /**
     * Looks after robots whose code ended without yielding, and warns about code that never yields.
     * Robots whose step was answered, or came less than a watch period ago, cost one volatile read.
     */
    void watch() {
        long unsent = gate.unsentNanos();
        if (unsent < WATCH_MS * 1_000_000L) {
            return;
        }
        if (gate.claimIfYielded()) {
            sendRequests();
            return;
        }
        long warnAfter = options.yieldWarningMs() * 1_000_000L;
        if (unsent > warnAfter && warnedStep != openStep) {
            warnedStep = openStep;
            LOG.warning(() -> "robot " + hello.name() + "'s code has not yielded for step " + openStep + " after "
                    + options.yieldWarningMs() + " ms; it should wait with ArUtil.sleep or a blocking call");
        }
    }

    private void end(RunEnd.Kind kind, String reason) {
        settle(kind, reason);
        close();
    }

    /** Fixes how the robot's part ended, if nothing has yet; the first end is the one that counts. */
    private void settle(RunEnd.Kind kind, String reason) {
        RunEnd e;
        synchronized (this) {
            if (runEnd != null) {
                return;
            }
            EnvironmentLink l = link;
            e = new RunEnd(hello.name(), kind, l == null ? "?" : l.environment(), openStep, reason);
            runEnd = e;
        }
        LOG.fine(e::describe);
        RobotRuntime rt = runtime;
        if (rt != null) {
            rt.runEndWatches().ended(this, e);
        }
    }

    private void close() {
        RobotRuntime rt = runtime;
        if (rt != null) {
            rt.unwatch(this);
        }
        gate.close();
        EnvironmentLink l = link;
        if (l != null) {
            l.close();
        }
        leaveRuntime();
    }

    /** The robot no longer uses its runtime, once its link has closed; the runtime closes after its last robot. */
    private void leaveRuntime() {
        RobotRuntime rt = runtime;
        if (rt != null && leftRuntime.compareAndSet(false, true)) {
            rt.leave();
        }
    }
}
