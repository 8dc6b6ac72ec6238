package robosim.viewer.net;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.protocol.Bye;
import robosim.protocol.FrameException;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.LogLimiter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;
import robosim.protocol.RunSecret;
import robosim.protocol.SecretLookup;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;

/**
 * The viewer side of the wire: attaches to an Environment's viewer port, says
 * {@link ViewerHello}, takes the {@link WorldDescription} that must come first, then passes the
 * {@link Snapshot}s that follow to its {@link SnapshotListener}s until a {@link Bye} or the end of
 * the stream. A later {@code WorldDescription} (a world reloaded by a control panel) is passed on
 * too, and replaces the world for the snapshots after it.
 *
 * <p>The listeners may draw images (see {@code robosim.viewer.draw}), record the run or feed a
 * window; the client itself draws nothing. They are told of the end ({@link SnapshotListener#end}) only when the Environment says
 * goodbye, and are closed when the run ends however it ends.
 *
 * <p>No wait is unbounded: the connection has {@link ViewerOptions#connectTimeout()} and each
 * message {@link ViewerOptions#readTimeout()}. Every failure ends {@link #run()} with a
 * {@link ViewerException} that names the Environment and the reason.
 */
public final class ViewerClient {
    private static final Logger LOG = Logger.getLogger(ViewerClient.class.getName());
    /** The line of a world received, which an Environment sends again as robots join: one a second. */
    private final LogLimiter worlds = new LogLimiter(LOG);
    /** How long to wait before connecting again while nothing listens, ms. */
    static final long RETRY_MS = 200;

    private final ViewerOptions options;
    private final List<SnapshotListener> listeners;
    private final MessageCodec codec = new MessageCodec();
    private volatile Socket socket;
    private volatile boolean stopped;

    /**
     * A client that passes the run to listeners.
     *
     * @param options  where to attach
     * @param listeners what follows the run, in order; each is closed when the run ends
     */
    public ViewerClient(ViewerOptions options, List<SnapshotListener> listeners) {
        if (options == null || listeners == null || listeners.stream().anyMatch(l -> l == null)) {
            throw new IllegalArgumentException("null was supplied for " + (options == null ? "options" : "listeners")
                    + ": it is required");
        }
        this.options = options;
        this.listeners = List.copyOf(listeners);
    }

    /** @return the options this client runs with */
    public ViewerOptions options() {
        return options;
    }

    /**
     * Detaches from another thread, as when the user closes the window: {@link #run()} then
     * returns with the end reason {@code "stopped"}.
     */
    public void stop() {
        stopped = true;
        Socket s = socket;
        if (s != null) {
            closeQuietly(s);
        }
    }

    /**
     * Attaches, passes the run on until the Environment says goodbye or closes the stream, and
     * detaches.
     *
     * @return what was received
     * @throws ViewerException if the Environment cannot be reached, is silent for longer than the
     *                         read timeout, breaks the protocol, or a listener fails
     */
    public ViewerSummary run() throws ViewerException {
        long deadline = System.nanoTime() + options.connectTimeout().toNanos();
        SecretLookup lookup;
        try {
            // found now too, so that a secret that breaks its rule is said before any connection
            String first = RunSecret.find(null, options.host(), options.port());
            lookup = new SecretLookup(options.host(), options.port(), first);
        } catch (IllegalArgumentException e) {
            throw new ViewerException("cannot attach to the environment at " + options.peer() + ": " + e.getMessage(), e);
        }
        while (true) {
            try {
                return attach(lookup, deadline);
            } catch (ViewerException e) {
                // a refusal of a secret found before the Environment wrote its own clears (RunSecret.mayClear)
                if (stopped || e.refusal() == null || !lookup.clears(e.refusal()) || System.nanoTime() - deadline > 0) {
                    if (e.refusal() != null) {
                        new Session().abandon(); // kept open for a retry that does not come: closed now
                    }
                    throw e;
                }
                LOG.info(() -> "viewer '" + options.name() + "': the environment at " + options.peer() + " refused the"
                        + " run secret found, and another has appeared since; trying again");
            }
        }
    }

    /** One attempt: connects (trying again until the deadline while nothing listens), says hello and follows the run. */
    private ViewerSummary attach(SecretLookup token, long deadline) throws ViewerException {
        Session session = new Session();
        try {
            socket = connect(deadline);
            if (stopped) {
                closeQuietly(socket);
            }
            socket.setSoTimeout(Math.toIntExact(options.readTimeout().toMillis()));
            new FrameWriter(socket.getOutputStream(), codec).write(new ViewerHello(options.name(), token.get()));
            return session.run(new FrameReader(socket.getInputStream(), codec, options.maxFrame()));
        } catch (ViewerException e) {
            if (e.refusal() == null) {
                session.abandon();
            }
            throw e;
        } catch (IOException e) {
            session.abandon();
            if (stopped) {
                return session.summary("stopped");
            }
            throw new ViewerException("cannot greet the environment at " + options.peer() + ": "
                    + e.getClass().getSimpleName() + ": " + e.getMessage(), e);
        } finally {
            if (socket != null) {
                closeQuietly(socket);
            }
        }
    }

    /** Connects, trying again every {@value #RETRY_MS} ms while nothing listens (an Environment starting), until the deadline. */
    private Socket connect(long deadline) throws ViewerException {
        while (true) {
            int timeoutMs = Math.toIntExact(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
            Socket s = new Socket();
            try {
                s.connect(new InetSocketAddress(options.host(), options.port()), timeoutMs);
                LOG.info(() -> "viewer '" + options.name() + "' connected to the environment at " + options.peer());
                return s;
            } catch (IOException e) {
                closeQuietly(s);
                boolean again = e instanceof ConnectException && !stopped
                        && deadline - System.nanoTime() > TimeUnit.MILLISECONDS.toNanos(RETRY_MS);
                if (again) {
                    try {
                        Thread.sleep(RETRY_MS);
                        continue;
                    } catch (InterruptedException ie) {
                        Thread.currentThread().interrupt();
                    }
                }
                String why = e instanceof SocketTimeoutException ? "no answer within "
                        + options.connectTimeout().toMillis() + " ms (connectTimeout)"
                        : e.getClass().getSimpleName() + ": " + e.getMessage()
                        + (e instanceof ConnectException ? " (tried for " + options.connectTimeout().toMillis()
                        + " ms, connectTimeout)" : "");
                throw new ViewerException("cannot connect to the environment at " + options.peer() + ": " + why, e);
            }
        }
    }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException e) {
            LOG.log(Level.FINE, "closing a viewer socket failed", e);
        }
    }

    /** One attachment's reading loop and counters. */
    private final class Session {
        private String world;
        private long received;
        private long lastStep = -1;
        private boolean closed;

        ViewerSummary run(FrameReader in) throws ViewerException {
            Message first = read(in, "the world description");
            if (first == null) {
                throw fail("closed the connection before sending the world description", null);
            }
            if (first instanceof Bye bye) {
                throw new ViewerException("the environment at " + options.peer() + " sent no world: " + bye.reason(), null,
                        bye.reason().startsWith(Bye.REFUSED) ? bye.reason() : null);
            }
            if (!(first instanceof WorldDescription description)) {
                throw fail("broke the protocol: the first message must be a world description, not "
                        + first.getClass().getSimpleName(), null);
            }
            accept(description);
            while (true) {
                Message m = read(in, "a frame");
                if (m == null || m instanceof Bye) {
                    String reason = m == null ? (stopped ? "stopped" : "end of stream") : ((Bye) m).reason();
                    if (m != null) {
                        tell(l -> l.end(reason));
                    }
                    closeListeners();
                    ViewerSummary summary = summary(reason);
                    LOG.info(() -> "viewer '" + options.name() + "' detached from " + options.peer() + ": "
                            + summary.describe());
                    return summary;
                } else if (m instanceof Snapshot snapshot) {
                    if (received == 0 || snapshot.step() != lastStep) {
                        received++; // step 0 comes again as the run starts: one step, one snapshot
                    }
                    lastStep = snapshot.step();
                    tell(l -> l.snapshot(snapshot));
                } else if (m instanceof WorldDescription reloaded) {
                    accept(reloaded);
                } else {
                    throw fail("broke the protocol after step " + lastStep + ": a viewer expects frames, not "
                            + m.getClass().getSimpleName(), null);
                }
            }
        }

        private void accept(WorldDescription description) throws ViewerException {
            world = description.name();
            worlds.info("worlds received", () -> "world '" + LogLimiter.excerpt(description.name()) + "' from "
                    + options.peer() + ": " + description.width()
                    + " x " + description.height() + " mm, " + description.obstacles().size() + " obstacles, "
                    + description.robots().size() + " robots");
            for (SnapshotListener l : listeners) {
                try {
                    l.world(description);
                } catch (IOException | RuntimeException e) {
                    throw fail("sent world '" + LogLimiter.excerpt(description.name()) + "', which a listener cannot take: "
                            + e.getMessage(), e);
                }
            }
        }

        ViewerSummary summary(String reason) {
            return new ViewerSummary(world, received, lastStep, reason);
        }

        /** A call on a listener, which may fail. */
        private interface Call {
            void on(SnapshotListener listener) throws IOException;
        }

        private void tell(Call call) throws ViewerException {
            for (SnapshotListener l : listeners) {
                try {
                    call.on(l);
                } catch (IOException | RuntimeException e) {
                    throw new ViewerException("cannot store the frame of step " + lastStep + " from "
                            + options.peer() + ": " + e.getMessage(), e);
                }
            }
        }

        private void closeListeners() throws ViewerException {
            closed = true;
            tell(SnapshotListener::close);
        }

        /** Closes the listeners after a failure, logging rather than hiding it. */
        void abandon() {
            if (closed) {
                return;
            }
            closed = true;
            for (SnapshotListener l : listeners) {
                try {
                    l.close();
                } catch (IOException | RuntimeException e) {
                    LOG.log(Level.FINE, "closing a listener after a failure failed", e);
                }
            }
        }

        private Message read(FrameReader in, String expected) throws ViewerException {
            try {
                return in.read();
            } catch (IOException e) {
                if (stopped) {
                    return null;
                }
                if (e instanceof SocketTimeoutException) {
                    throw fail("sent nothing for " + options.readTimeout().toMillis() + " ms (readTimeout) while "
                            + "the viewer waited for " + expected + after(), e);
                }
                if (e instanceof FrameException) {
                    throw fail("broke the protocol" + after() + ": " + e.getMessage(), e);
                }
                throw fail("dropped the connection" + after() + ": " + e.getClass().getSimpleName() + ": "
                        + e.getMessage(), e);
            }
        }

        private String after() {
            return lastStep < 0 ? "" : " after step " + lastStep;
        }

        private ViewerException fail(String what, Throwable cause) {
            return new ViewerException("the environment at " + options.peer() + " " + what, cause);
        }
    }
}
