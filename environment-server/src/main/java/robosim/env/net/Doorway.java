package robosim.env.net;

import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import robosim.protocol.LogLimiter;
import robosim.protocol.MessageCodec;

/**
 * The Environment's two listening sockets and the connections they bring in, held to the caps of
 * {@link Limits}: at most {@link Limits#maxPending()} connections without a hello (at the cap the
 * oldest silent one makes room, or, in a burst of new ones, accepting waits and new connections
 * wait in the listen backlog), each closed if it says no
 * hello by the deadline; viewers and control clients closed when idle; accepting paused a moment
 * after it fails (a full file table) instead of spinning, with the failures logged once a period.
 * Served by the step loop's thread; the list of connections may be read from any thread.
 */
final class Doorway {
    private static final Logger LOG = Logger.getLogger(EnvironmentServer.class.getName());
    private static final long MAX_QUEUED_ROBOT = 1 << 20;
    /** How often the caps on waiting and idle connections are checked. */
    private static final long CHECK_NANOS = TimeUnit.MILLISECONDS.toNanos(100);
    /** How long accepting pauses after it failed, so that a full file table does not spin the loop. */
    private static final long ACCEPT_PAUSE_NANOS = TimeUnit.MILLISECONDS.toNanos(100);
    /** The period of the warnings about accepting: one line of each kind in it, then the count. */
    private static final long LOG_PERIOD_MS = 10_000;
    private static final String ACCEPT_FAILURES = "accept failures";
    private static final String TURNED_AWAY = "warnings about connections without a hello";
    /** How long a connection may be silent before it may be closed to make room for another. */
    private static final long SILENT_NANOS = TimeUnit.SECONDS.toNanos(1);

    private final ServerOptions options;
    private final MessageCodec codec;
    private final SessionRules rules;
    private final List<Connection> all = new CopyOnWriteArrayList<>();
    private final LogLimiter warnings = new LogLimiter(LOG, LOG_PERIOD_MS);
    /** The limiter of the log lines of every connection this doorway accepts. */
    private final LogLimiter connectionLog = Connection.newLog();
    private final InProcessDoor inProcess;
    private Selector selector;
    private ServerSocketChannel robotChannel;
    private ServerSocketChannel viewerChannel;
    private long nextCheck;
    private long acceptPausedUntil;
    private boolean acceptPaused;
    private boolean pausedForPending;

    Doorway(ServerOptions options, MessageCodec codec, SessionRules rules) {
        this.options = options;
        this.codec = codec;
        this.rules = rules;
        this.inProcess = new InProcessDoor(codec, connectionLog);
    }

    /** @return the door for robots of this JVM, which the step loop drains as it serves sockets */
    InProcessDoor inProcess() {
        return inProcess;
    }

    /**
     * Takes an in-process link's connection as if accepted: it must say hello like any other,
     * but its robots present no secret, since no other user can reach it.
     */
    void adopt(Connection c) {
        all.removeIf(Connection::isClosed);
        all.add(c);
    }

    /**
     * Opens both listening sockets on the selector.
     *
     * @throws IOException           if a port cannot be bound; its message names the port (robot or viewer)
     * @throws IllegalStateException if the address is not a loopback address and the run has no secret
     */
    void bind(Selector on) throws IOException {
        InetAddress addr = InetAddress.getByName(options.bindAddress());
        if (!addr.isLoopbackAddress() && !options.access().guarded()) {
            throw new IllegalStateException("refusing to listen on " + options.bindAddress() + " without a run secret:"
                    + " anyone who can reach that address could join, watch and change the run; give the run a"
                    + " secret, or listen on 127.0.0.1");
        }
        selector = on;
        inProcess.bind(on);
        robotChannel = listen(new InetSocketAddress(addr, options.robotPort()), Connection.Kind.ROBOT);
        viewerChannel = listen(new InetSocketAddress(addr, options.viewerPort()), Connection.Kind.VIEWER);
    }

    private ServerSocketChannel listen(InetSocketAddress at, Connection.Kind kind) throws IOException {
        ServerSocketChannel ch = ServerSocketChannel.open();
        try {
            ch.bind(at, 128);
        } catch (IOException e) {
            ch.close();
            // two ports are listened on: say which one could not be had
            throw new BindException("cannot listen on the " + (kind == Connection.Kind.ROBOT ? "robot" : "viewer")
                    + " port " + at.getAddress().getHostAddress() + ":" + at.getPort() + ": " + e.getMessage());
        }
        ch.configureBlocking(false);
        ch.register(selector, SelectionKey.OP_ACCEPT, kind);
        return ch;
    }

    int robotPort() {
        return robotChannel.socket().getLocalPort();
    }

    int viewerPort() {
        return viewerChannel.socket().getLocalPort();
    }

    /** @return every connection not yet found closed, in the order accepted */
    List<Connection> connections() {
        return all;
    }

    /** Accepts a connection that is waiting on a listening socket, within the caps. */
    void accept(ServerSocketChannel server, Connection.Kind kind) {
        SocketChannel ch;
        try {
            ch = server.accept();
        } catch (IOException e) {
            // most often the file table is full: stop accepting a moment instead of spinning on it
            long now = System.nanoTime();
            warnings.warning(ACCEPT_FAILURES, () -> "accepting a " + kind.name().toLowerCase()
                    + " connection failed: "
                    + e.getMessage() + "; accepting pauses " + TimeUnit.NANOSECONDS.toMillis(ACCEPT_PAUSE_NANOS)
                    + " ms");
            acceptPaused = true;
            acceptPausedUntil = now + ACCEPT_PAUSE_NANOS;
            setAccepting(false);
            return;
        }
        if (ch == null) {
            return;
        }
        all.removeIf(Connection::isClosed);
        try {
            long limit = kind == Connection.Kind.ROBOT ? MAX_QUEUED_ROBOT : options.limits().viewerBudget();
            all.add(new Connection(kind, ch, selector, codec, options.maxFrame(), limit, connectionLog));
        } catch (IOException e) {
            warnings.warning(ACCEPT_FAILURES, () -> "setting up a " + kind.name().toLowerCase()
                    + " connection failed: " + e.getMessage());
            try {
                ch.close();
            } catch (IOException again) {
                LOG.fine("closing a connection that failed: " + again.getMessage());
            }
            return;
        }
        long now = System.nanoTime();
        if (!makeRoomForHellos(now) && !pausedForPending) {
            // the next connections wait in the listen backlog until these say hello
            pausedForPending = true;
            setAccepting(false);
            warnings.warning(TURNED_AWAY, () -> pending() + " connections have not said hello yet, the most this"
                    + " Environment allows (--max-pending); new connections wait until some do");
        }
    }

    /**
     * Keeps the cap on connections without a hello. An honest client says hello within
     * milliseconds of connecting, so at the cap the oldest connection that has been silent for
     * {@link #SILENT_NANOS} is closed to make room, which keeps a flood of silent connections from
     * holding the slots; if all are younger (a burst of honest robots), accepting waits and the
     * next connections wait in the listen backlog until these say hello.
     *
     * @return whether there is room for one more
     */
    private boolean makeRoomForHellos(long now) {
        long max = options.limits().maxPending();
        while (pending() >= max) {
            Connection oldest = null;
            for (Connection c : all) {
                if (!c.isClosed() && !c.greeted() && (oldest == null || c.acceptedNanos() < oldest.acceptedNanos())) {
                    oldest = c;
                }
            }
            if (oldest == null || now - oldest.acceptedNanos() < SILENT_NANOS) {
                return false;
            }
            Connection closing = oldest;
            warnings.warning(TURNED_AWAY, () -> "closing a " + closing.kind.name().toLowerCase() + " connection from "
                    + closing.address() + " that said no hello for " + TimeUnit.NANOSECONDS.toMillis(now
                    - closing.acceptedNanos()) + " ms, to make room: " + max + " connections without a hello is the"
                    + " most this Environment allows (--max-pending)");
            closing.shut();
        }
        return true;
    }

    /** After the ready connections were served: takes the next waiting ones once these have said hello. */
    void served() {
        if (pausedForPending) {
            // a burst of honest robots says hello at once: take the next ones as soon as these have
            resumeAccepting(System.nanoTime());
        }
    }

    /**
     * Keeps the caps on connections that wait, if a check is due: closes those that said no hello
     * in time and viewers and control clients idle too long, resumes accepting after a pause, and
     * logs the counts of warnings held back.
     *
     * @param now {@link System#nanoTime()}
     * @return when the next check is due, {@link System#nanoTime()}: the step loop's select waits no longer
     */
    long check(long now) {
        if (now - nextCheck < 0) {
            return nextCheck;
        }
        nextCheck = now + CHECK_NANOS;
        Limits limits = options.limits();
        long helloNanos = TimeUnit.MILLISECONDS.toNanos(limits.helloDeadlineMs());
        long idleNanos = TimeUnit.MILLISECONDS.toNanos(limits.idleTimeoutMs());
        for (Connection c : all) {
            if (c.isClosed()) {
                continue;
            }
            if (!c.greeted()) {
                if (now - c.acceptedNanos() > helloNanos) {
                    warnings.warning(TURNED_AWAY, () -> "closing a " + c.kind.name().toLowerCase()
                            + " connection from "
                            + c.address() + ": it said no hello within " + limits.helloDeadlineMs() + " ms");
                    c.shut();
                }
            } else if (c.kind == Connection.Kind.VIEWER) {
                closeIfIdle(c, now, idleNanos);
            }
        }
        all.removeIf(Connection::isClosed);
        if (acceptPaused || pausedForPending) {
            resumeAccepting(now);
        }
        warnings.flush();
        connectionLog.flush();
        return nextCheck;
    }

    private void closeIfIdle(Connection c, long now, long idleNanos) {
        long ms = options.limits().idleTimeoutMs();
        if (c.queuedBytes() > 0 && now - c.lastWriteNanos() > idleNanos) {
            c.close("it took nothing of what was sent to it for " + ms + " ms (--idle-timeout)");
            rules.closed(c, "idle");
        } else if (c.isControl() && now - c.lastReadNanos() > idleNanos) {
            c.close("it sent nothing for " + ms + " ms (--idle-timeout)");
            rules.closed(c, "idle");
        }
    }

    private long pending() {
        long n = 0;
        for (Connection c : all) {
            if (!c.isClosed() && !c.greeted()) {
                n++;
            }
        }
        return n;
    }

    private void setAccepting(boolean on) {
        for (ServerSocketChannel ch : List.of(robotChannel, viewerChannel)) {
            SelectionKey key = ch.keyFor(selector);
            if (key != null && key.isValid()) {
                key.interestOps(on ? SelectionKey.OP_ACCEPT : 0);
            }
        }
    }

    /** Accepts again once neither a failure's pause nor the cap on connections without a hello holds it. */
    private void resumeAccepting(long now) {
        if (acceptPaused && now - acceptPausedUntil >= 0) {
            acceptPaused = false;
        }
        if (pausedForPending && makeRoomForHellos(now)) {
            pausedForPending = false;
        }
        if (!acceptPaused && !pausedForPending) {
            setAccepting(true);
        }
    }

    /** Stops listening and closes every connection; any thread may call it. */
    void close() {
        inProcess.close();
        for (Connection c : all) {
            c.shut();
        }
        for (java.io.Closeable ch : new java.io.Closeable[] {robotChannel, viewerChannel}) {
            if (ch != null) {
                try {
                    ch.close();
                } catch (IOException e) {
                    LOG.fine("closing: " + e.getMessage());
                }
            }
        }
    }
}
