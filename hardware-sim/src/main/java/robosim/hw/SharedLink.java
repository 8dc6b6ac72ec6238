package robosim.hw;

import java.io.IOException;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Supplier;
import java.util.logging.Logger;
import robosim.protocol.LogLimiter;
import robosim.protocol.Bye;
import robosim.protocol.KeepAlive;
import robosim.protocol.LinkHello;
import robosim.protocol.LinkRequests;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.TimeSteps;
import robosim.protocol.Welcome;

/**
 * One connection to an Environment that many robots of a {@link RobotRuntime} share (over TCP, or
 * in-process to an Environment of the same JVM: see {@link MessageLine}): each step one
 * {@link TimeSteps} frame in, read by one thread that hands each robot its state (the robots of a
 * large frame in chunks, on one thread per processor, since each robot's cycle runs as its state is
 * handed over: {@link SharedLinks#handers()}), and one
 * {@link LinkRequests} frame out, written by the thread that completes it (the last robot to
 * yield). Each robot keeps its own {@link HardwareSimulator}, request queue and state. When some
 * robots are late, the requests of the others go after {@link #LINGER_MS} in a frame of their own,
 * so that only the late ones miss the Environment's step deadline. As on a robot's own connection, a
 * {@link KeepAlive} is only a sign of life, and an Environment silent for
 * {@link HardwareOptions#lostAfterMs()} is lost for every robot of the link.
 */
final class SharedLink {
    private static final Logger LOG = Logger.getLogger(SharedLink.class.getName());
    private final LogLimiter strayWelcomes = new LogLimiter(LOG);
    /** How long a step's requests wait for late robots of the link before the ready ones are sent. */
    static final long LINGER_MS = 100;
    /** Robots whose states one task hands out; a frame of fewer than two chunks is handed out by the reader. */
    static final int HANDING_CHUNK = 25;
    private final SharedLinks owner;
    private final String host;
    private final int port;
    private final HardwareOptions options;
    private final MessageLine line;
    private final Map<String, LinkMember> members = new ConcurrentHashMap<>();
    private final Map<String, Joining> joining = new ConcurrentHashMap<>();
    /** The open step's requests, guarded by this. */
    private long batchStep;
    private final Set<LinkMember> expected = new LinkedHashSet<>();
    private List<LinkRequests.ForRobot> batch = new ArrayList<>();
    private long batchOpenedNanos;
    private volatile String endReason;
    /** The secret the link's hello presented. */
    private String presented;
    /** The Environment's reason, when it refused the link. */
    private volatile String refusal;

    private record Joining(LinkMember member, CompletableFuture<Welcome> welcome) {
    }

    /**
     * Says the link's hello on an open line; {@link #read} is to run on a thread of its own.
     *
     * @param owner   the runtime's links, told when this one ends
     * @param host    the Environment's host
     * @param port    its robot port
     * @param options timeouts (the first robot's serve the whole link)
     * @param secret  gives the run secret the link presents (the opening robot's)
     * @param line    the line to the Environment, open; closed here if the hello cannot be said
     * @throws IOException if the hello cannot be said
     */
    SharedLink(SharedLinks owner, String host, int port, HardwareOptions options, Supplier<String> secret,
               MessageLine line) throws IOException {
        this.owner = owner;
        this.host = host;
        this.port = port;
        this.options = options;
        this.line = line;
        try {
            presented = secret.get();
            line.write(new LinkHello("pid " + ProcessHandle.current().pid(), presented));
        } catch (IOException | RuntimeException e) {
            line.close();
            throw e;
        }
    }

    /** @return whether the link has ended: a robot that comes later opens a new one */
    boolean hasEnded() {
        return endReason != null;
    }

    /** @return the Environment's host and port, {@code host:port} */
    String environment() {
        return host + ":" + port;
    }

    /**
     * Sends the requests of the robots that are ready, if the open step's frame has waited
     * {@link #LINGER_MS} for the others.
     *
     * @param now {@link System#nanoTime()} now
     */
    void sendLingering(long now) {
        LinkRequests ready;
        synchronized (this) {
            ready = batch.isEmpty() || now - batchOpenedNanos < TimeUnit.MILLISECONDS.toNanos(LINGER_MS)
                    ? null : takeBatch();
        }
        write(ready);
    }

    /** Says a robot's hello on the link and waits (bounded) for its welcome or refusal. */
    Welcome join(LinkMember m, RobotHello hello) throws IOException {
        String name = hello.name();
        Joining j = new Joining(m, new CompletableFuture<>());
        if (members.containsKey(name) || joining.putIfAbsent(name, j) != null) {
            throw new IOException("robot " + name + " is already connected from this program");
        }
        try {
            if (endReason != null) {
                // the link ended just before this robot's hello: a refusal of the link is the robot's too
                throw refusal != null ? RefusedException.ofLink(endReason, refusal, presented) : new IOException(endReason);
            }
            line.write(hello);
            return j.welcome().get(options.connectTimeoutMs(), TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            throw new SocketTimeoutException("the Environment at " + host + ":" + port + " did not welcome robot "
                    + name + " within " + options.connectTimeoutMs() + " ms");
        } catch (ExecutionException e) {
            throw e.getCause() instanceof IOException io ? io : new IOException(e.getCause());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while connecting", e);
        } finally {
            joining.remove(name);
        }
    }

    /** Reads the Environment's messages until the link ends; runs on the link's own thread. */
    void read() {
        RunEnd.Kind kind = RunEnd.Kind.LOST;
        String reason = SocketLink.CLOSED;
        try {
            Message m;
            while ((m = line.read()) != null) {
                if (m instanceof TimeSteps ts) {
                    steps(ts);
                } else if (m instanceof KeepAlive) {
                    continue; // a sign of life: the read's timeout starts again
                } else if (m instanceof Welcome w) {
                    welcomed(w);
                } else if (m instanceof Bye bye && bye.robot() != null) {
                    byeTo(bye.robot(), bye.reason());
                } else if (m instanceof Bye bye) {
                    kind = RunEnd.ofBye(bye.reason());
                    reason = RunEnd.withoutPrefix(bye.reason());
                    break;
                } else {
                    reason = "it sent " + SocketLink.describe(m);
                    break;
                }
            }
        } catch (SocketTimeoutException e) {
            reason = SocketLink.silent(options);
        } catch (IOException e) {
            reason = "the connection failed: " + e.getMessage();
        }
        endAll(kind, reason);
    }

    private void welcomed(Welcome w) {
        Joining j = joining.get(w.name());
        if (j == null) {
            strayWelcomes.warning("welcomes of robots that did not say hello", () -> "the Environment at " + host
                    + ":" + port + " welcomed robot " + LogLimiter.excerpt(w.name())
                    + ", which did not say hello on this link");
            return;
        }
        // a member from now: the first step may come before the joining thread wakes
        members.put(w.name(), j.member());
        j.welcome().complete(w);
    }

    private void byeTo(String robot, String reason) {
        Joining j = joining.get(robot);
        if (j != null && !j.welcome().isDone()) {
            j.welcome().completeExceptionally(new RefusedException("the Environment at " + host + ":" + port + " "
                    + reason, RunEnd.withoutPrefix(reason)));
            return;
        }
        LinkMember m = members.get(robot);
        if (m != null) {
            m.ended(RunEnd.ofBye(reason), RunEnd.withoutPrefix(reason));
        }
    }

    private void steps(TimeSteps ts) {
        List<LinkMember> to = new ArrayList<>(ts.robots().size());
        synchronized (this) {
            // a step's states may come in several frames: the first opens the step
            if (ts.step() != batchStep) {
                batchStep = ts.step();
                batch = new ArrayList<>();
                batchOpenedNanos = System.nanoTime();
                expected.clear();
            }
            for (TimeSteps.ForRobot r : ts.robots()) {
                LinkMember m = members.get(r.robot());
                to.add(m);
                if (m != null) {
                    expected.add(m);
                }
            }
        }
        ExecutorService handers = to.size() < 2 * HANDING_CHUNK ? null : owner.handers();
        if (handers == null) {
            hand(ts, to, 0, to.size());
            return;
        }
        // each robot's cycle (its range devices' buffers, its tasks) is its own: hand them out in
        // chunks, as each robot's own link thread would run them, and go back to reading
        for (int from = 0; from < to.size(); from += HANDING_CHUNK) {
            int start = from;
            handers.execute(() -> hand(ts, to, start, Math.min(to.size(), start + HANDING_CHUNK)));
        }
    }

    /** Hands robots {@code from} to {@code to} (exclusive) of a frame their states. */
    private void hand(TimeSteps ts, List<LinkMember> members, int from, int to) {
        for (int i = from; i < to; i++) {
            LinkMember m = members.get(i);
            if (m != null) {
                m.receiver().step(new RobotSensorResponse(ts.step(), ts.robots().get(i).state()));
            } else {
                // a robot that left while this step was on its way
                String robot = ts.robots().get(i).robot();
                LOG.fine(() -> "the Environment at " + host + ":" + port + " sent a step to robot " + robot
                        + ", which is no longer on this link");
            }
        }
    }

    /** Adds a robot's requests to the open step's frame, and sends the frame if it is now complete. */
    void submit(LinkMember m, long step, List<RobotRequest> requests) {
        LinkRequests complete;
        synchronized (this) {
            if (step != batchStep || !expected.remove(m)) {
                return; // the robot was dropped from this step, or this is a second answer: the Environment has moved on
            }
            batch.add(new LinkRequests.ForRobot(m.name(), SocketLink.commands(requests)));
            complete = expected.isEmpty() ? takeBatch() : null;
        }
        write(complete);
    }

    /** @return the requests collected for the open step, which start afresh; call holding the lock */
    private LinkRequests takeBatch() {
        LinkRequests frame = new LinkRequests(batchStep, batch);
        batch = new ArrayList<>();
        return frame;
    }

    /** Writes a message, if any; a failed write ends the link for all its robots. */
    void write(Message m) {
        if (m == null) {
            return;
        }
        try {
            line.write(m);
        } catch (IOException e) {
            endAll(RunEnd.Kind.LOST, "sending requests failed: " + e.getMessage());
        }
    }

    /** A robot's part closed: the step's frame no longer waits for it. */
    void leave(LinkMember m) {
        members.remove(m.name(), m);
        LinkRequests complete;
        synchronized (this) {
            complete = expected.remove(m) && expected.isEmpty() && !batch.isEmpty() ? takeBatch() : null;
        }
        write(complete);
    }

    /**
     * Closes the link, its robots having all left: the runtime is closing.
     *
     * @param reason why, for the log
     */
    void close(String reason) {
        endAll(RunEnd.Kind.LEFT, reason);
    }

    private void endAll(RunEnd.Kind kind, String reason) {
        synchronized (this) {
            if (endReason != null) {
                return;
            }
            if (kind == RunEnd.Kind.REFUSED) {
                refusal = reason;
            }
            endReason = "the Environment at " + host + ":" + port + ": " + reason;
        }
        owner.ended(this);
        line.close();
        for (Joining j : joining.values()) {
            // a link refused (its secret) refuses the robots that were joining on it
            j.welcome().completeExceptionally(kind == RunEnd.Kind.REFUSED ? RefusedException.ofLink(endReason, reason, presented)
                    : new IOException(endReason));
        }
        for (LinkMember m : members.values()) {
            m.ended(kind, reason);
        }
    }
}
