package robosim.pioneer.server;

import java.io.Closeable;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.util.Optional;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.IntConsumer;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.hw.RunEnd;
import robosim.pioneer.ConfigPacket;
import robosim.pioneer.PioneerPacket;
import robosim.pioneer.RobotIdentity;
import robosim.protocol.LogLimiter;

/**
 * One robot's Pioneer port. It accepts one ARIA client at a time (a second is refused at once, with a
 * log line at most once a second, after a moment's wait when the first may be leaving); the first client to finish the handshake brings the robot into the run as a
 * {@link BridgeRobot}, which stays for the clients after it. The handshake and the client's commands
 * are answered at once, whatever the Environment is doing. When a program on the Environment's robot
 * port drives the robot already, the Environment refuses the bridge and the client is closed with
 * the reason in the log.
 */
final class PioneerPort implements Closeable {
    private static final Logger LOG = Logger.getLogger(PioneerPort.class.getName());
    private static final LogLimiter LIMITED = new LogLimiter(LOG);
    /**
     * Connections the system holds until they are accepted: a burst of connections beyond it waits a
     * second for the system to take it again, so it is deep enough for a flood to be refused at the
     * rate it comes.
     */
    static final int BACKLOG = 1024;
    /** How long a connection that finds the port taken may wait for it, ms. */
    static final int WAIT_MS = 500;
    private static final int WAIT_CHECK_MS = 20;
    /** Checks the waiting connections of every port. */
    private static final ScheduledExecutorService WAITS = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "pioneer-port-waits");
        t.setDaemon(true);
        return t;
    });

    private final ServedRobot served;
    private final ServerSocket server;
    private final PioneerPortOptions options;
    private final String envHost;
    private final int envPort;
    private final String secret;
    private final IntConsumer simExit;
    private volatile boolean closed;
    private volatile BridgeRobot bridge;
    private volatile PioneerSession current;
    /** A connection that found the port taken and waits a moment for it; guarded by this. */
    private Socket waiting;
    private long waitingUntilNanos;
    private ScheduledFuture<?> waitingCheck;

    PioneerPort(ServedRobot served, InetAddress bind, int port, PioneerPortOptions options, String envHost, int envPort,
                String secret, IntConsumer simExit) throws IOException {
        this.served = served;
        this.options = options;
        this.envHost = envHost;
        this.envPort = envPort;
        this.secret = secret;
        this.simExit = simExit;
        requireFits(served);
        server = new ServerSocket();
        try {
            server.bind(new InetSocketAddress(bind, port), BACKLOG);
        } catch (IOException e) {
            server.close();
            throw new IOException("robot " + served.name() + "'s Pioneer port " + bind.getHostAddress() + ":" + port
                    + " cannot listen: " + e.getMessage(), e);
        }
        Thread t = new Thread(this::accept, "pioneer-port-" + port());
        t.setDaemon(true);
        t.start();
    }

    /**
     * The robot's name, class and subclass go into the SYNC2 answer and the CONFIG reply, which ARIA
     * reads only up to {@value PioneerPacket#ARIA_LIMIT} bytes.
     *
     * @throws IllegalArgumentException naming the robot when they are too long
     */
    static void requireFits(ServedRobot r) {
        String name = r.name();
        String robotClass = r.parameters().robotClass();
        String subclass = r.parameters().subclass();
        int longest;
        try {
            longest = Math.max(new RobotIdentity(name, robotClass, subclass).toPacket().encode().length,
                    new ConfigPacket(robotClass, subclass, "SIM", 0, 0, 0, 0, name, 0, false, false, false, 0, 0, 0, 0,
                            0, 0, 0, 0, 0, CommandHandler.FIRMWARE).toPacket().encode().length);
        } catch (IllegalArgumentException tooLong) {
            longest = Integer.MAX_VALUE;
        }
        if (longest > PioneerPacket.ARIA_LIMIT) {
            throw new IllegalArgumentException("robot " + name + "'s name, class and subclass (" + (name.length()
                    + robotClass.length() + subclass.length()) + " characters) are too long for the Pioneer protocol's "
                    + PioneerPacket.ARIA_LIMIT + "-byte packets; shorten them to serve it on a Pioneer port");
        }
    }

    /** @return the port it listens on */
    int port() {
        return server.getLocalPort();
    }

    /** @return the robot it serves */
    ServedRobot robot() {
        return served;
    }

    private void accept() {
        while (!closed) {
            Socket s;
            try {
                s = server.accept();
            } catch (IOException e) {
                if (!closed) {
                    LOG.log(Level.WARNING, "robot " + served.name() + "'s Pioneer port stopped accepting", e);
                }
                return;
            }
            admit(s);
        }
    }

    /**
     * Takes a connection without waiting: it is served at once when the port is free, or when the
     * client there has not begun its handshake or has been silent for long ({@link
     * PioneerSession#isGivingWay()}). Else it waits for the port, for at most {@value #WAIT_MS} ms,
     * in case the client there has just said CLOSE and is not yet seen off; only the latest such
     * connection waits, and the one it replaces is refused at once, so a flood of connections is
     * refused as fast as it comes.
     */
    private synchronized void admit(Socket s) {
        if (takeFrom(current, s)) {
            serve(s);
        } else {
            letWait(s);
        }
    }

    /**
     * Whether a connection may have the port: it is free, or the client there has sent nothing or
     * has been silent for long, and is ended to make room.
     */
    private static boolean takeFrom(PioneerSession there, Socket s) {
        if (there == null || there.isEnded()) {
            return true;
        }
        String why = !there.isHeard() ? "it sent nothing" : there.isGivingWay()
                ? "silent for " + there.silenceAllowedMs() + " ms" : null;
        if (why != null) {
            there.end(why + ", and the ARIA client from " + s.getRemoteSocketAddress() + " wants the port");
        }
        return why != null;
    }

    /** Serves a connection as the port's client; one that cannot be served is closed, with a line. */
    private void serve(Socket s) {
        try {
            s.setTcpNoDelay(true);
            PioneerSession session = new PioneerSession(s, served.name(), new RobotIdentity(served.name(),
                    served.parameters().robotClass(), served.parameters().subclass()), options.handshakeMs(),
                    options.silentMs());
            current = session;
            session.start(this::connected);
        } catch (IOException | RuntimeException e) {
            LIMITED.warning("failures to serve robot " + served.name() + "'s ARIA clients", () -> "robot "
                    + served.name() + ": could not serve the ARIA client at " + s.getRemoteSocketAddress() + ": "
                    + e.getMessage());
            close(s);
        }
    }

    /** Lets a connection wait for the port, in place of the one waiting, which is refused. */
    private void letWait(Socket s) {
        if (waiting != null) {
            refuse(waiting);
        }
        waiting = s;
        waitingUntilNanos = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
        if (waitingCheck == null) {
            waitingCheck = WAITS.scheduleWithFixedDelay(this::checkWaiting, WAIT_CHECK_MS, WAIT_CHECK_MS,
                    TimeUnit.MILLISECONDS);
        }
    }

    /** Serves the waiting connection once the port is free, or refuses it when its wait is over. */
    private synchronized void checkWaiting() {
        Socket s = waiting;
        boolean free = s != null && !closed && takeFrom(current, s);
        if (s != null && !closed && !free && System.nanoTime() - waitingUntilNanos < 0) {
            return;
        }
        waiting = null;
        waitingCheck.cancel(false);
        waitingCheck = null;
        if (s == null) {
            return;
        }
        if (free) {
            serve(s);
        } else {
            refuse(s); // the port closed, or the wait is over and the client there stays
        }
    }

    private void refuse(Socket s) {
        LIMITED.warning("connections refused by robot " + served.name() + "'s Pioneer port", () -> "robot "
                + served.name() + ": Pioneer port " + port() + " has a client already; the one from "
                + s.getRemoteSocketAddress() + " is closed (one client at a time)");
        close(s);
    }

    /**
     * A client finished the handshake: it is attached at once, on the session's reader, which never
     * waits on the Environment, so OPEN and CONFIG are answered as they come. The robot joins the run
     * on its own thread if it has not (a refusal ends the session, with the reason, and the next
     * client may try again); a robot whose part in the run has ended is not served again.
     */
    private void connected(PioneerSession session) {
        BridgeRobot b;
        synchronized (this) {
            if (closed) {
                session.end("the Pioneer port closed");
                return;
            }
            if (session != current || session.isEnded()) {
                session.end("another ARIA client took the port");
                return;
            }
            b = bridge;
            if (b != null && b.hasLeftRun()) {
                RunEnd end = b.getRunEnd();
                session.end("robot " + served.name() + "'s part in the run has ended"
                        + (end == null ? "" : " (" + end.describe() + ")"));
                return;
            }
            if (b == null || b.failedToJoin()) {
                b = new BridgeRobot(served, envHost, envPort, options);
                bridge = b;
                b.start(secret);
            }
        }
        b.attach(session, simExit);
    }

    /**
     * @return how the robot stood without a client to the end, for the run report; empty while a
     *         client drives it, or when no ARIA client brought it into the run
     */
    Optional<String> unattended() {
        BridgeRobot b = bridge;
        return b == null ? Optional.empty() : b.unattended();
    }

    private static void close(Socket s) {
        try {
            s.close();
        } catch (IOException e) {
            LOG.log(Level.FINE, "closing", e);
        }
    }

    @Override
    public void close() {
        synchronized (this) {
            closed = true;
            if (waiting != null) {
                refuse(waiting);
                waiting = null;
            }
        }
        try {
            server.close();
        } catch (IOException e) {
            LOG.log(Level.FINE, "closing", e);
        }
        PioneerSession s = current;
        if (s != null) {
            s.end("the Pioneer port closed");
        }
        BridgeRobot b = bridge;
        if (b != null) {
            b.cancel();
        }
    }
}
