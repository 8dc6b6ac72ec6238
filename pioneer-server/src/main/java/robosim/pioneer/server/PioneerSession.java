package robosim.pioneer.server;

import java.io.IOException;
import java.io.InputStream;
import java.io.InterruptedIOException;
import java.io.OutputStream;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Supplier;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.pioneer.Commands;
import robosim.pioneer.ConfigPacket;
import robosim.pioneer.PioneerPacket;
import robosim.pioneer.PacketDecoder;
import robosim.pioneer.RobotIdentity;
import robosim.protocol.LogLimiter;

/**
 * One ARIA client's connection to a robot's Pioneer port: the SYNC0, SYNC1, SYNC2 handshake, then
 * the client's commands handed to the robot's {@link CommandHandler}, and the robot's packets
 * written back. The client's bytes are read by a thread of the session's own, no faster than its
 * {@link InputBudget} allows; garbage, bad lengths and bad checksums are dropped with a log line (at
 * most one a second, with a count), never ending the session or the run. A client that has not finished the handshake within
 * the handshake time ({@link PioneerPortOptions#handshakeMs()}) is closed so that the port is free
 * again; one that has been silent for the silence allowed ({@link PioneerPortOptions#silentMs()})
 * gives way to the next client that connects ({@link #isGivingWay()}), since an
 * ARIA program that has connected its robot but not yet started its cycle sends nothing at all.
 */
final class PioneerSession {
    private static final Logger LOG = Logger.getLogger(PioneerSession.class.getName());
    private static final LogLimiter LIMITED = new LogLimiter(LOG);
    /** The most read at once, so that the budget is kept to within a few packets. */
    private static final int READ_BYTES = 512;
    private static final int CHECK_MS = 1000;
    /** The packets that may wait for a client that reads slowly. */
    static final int MAX_QUEUED = 256;

    private enum Phase { SYNC0, SYNC1, SYNC2, CONNECTED }

    private final Socket socket;
    private final OutputStream out;
    private final String client;
    private final String robot;
    private final RobotIdentity identity;
    private volatile Phase phase = Phase.SYNC0;
    private volatile boolean opened;
    private volatile boolean ended;
    private volatile long lastPacketNanos = System.nanoTime();
    /** Whether a whole packet has come from the client. */
    private volatile boolean heard;
    private int packetsTaken;
    private Consumer<PioneerSession> connected;
    private volatile CommandHandler handler;
    private volatile Supplier<ConfigPacket> config;
    private volatile Consumer<String> onEnd;
    private volatile String endReason;
    private final BlockingQueue<byte[]> outgoing = new ArrayBlockingQueue<>(MAX_QUEUED);
    private final long handshakeMs;
    private final long allowedSilenceMs;

    /**
     * @param socket   the client's connection
     * @param robot    the robot's name, for log lines
     * @param identity what SYNC2 answers
     * @param handshakeMs how long the client may take over the handshake before it is closed
     * @param silentMs    how long it may be silent before it gives way to the next client
     */
    PioneerSession(Socket socket, String robot, RobotIdentity identity, long handshakeMs, long silentMs)
            throws IOException {
        this.handshakeMs = handshakeMs;
        this.allowedSilenceMs = silentMs;
        this.socket = socket;
        this.out = socket.getOutputStream();
        this.client = socket.getRemoteSocketAddress().toString();
        this.robot = robot;
        this.identity = identity;
    }

    /**
     * Starts reading the client's packets.
     *
     * @param connected told, on the session's thread, when the handshake is done; it
     *                  {@link #attach attaches} the robot, or ends the session
     */
    void start(Consumer<PioneerSession> connected) {
        this.connected = connected;
        Thread t = new Thread(this::read, "pioneer-" + robot);
        t.setDaemon(true);
        t.start();
        Thread w = new Thread(this::write, "pioneer-write-" + robot);
        w.setDaemon(true);
        w.start();
    }

    /**
     * Gives the session its robot, at once when the handshake is done: from then the session answers
     * OPEN, CONFIG, PULSE and the client's commands itself, whatever the Environment is doing.
     *
     * @param commands carries out the commands
     * @param config   the answer to CONFIG, as the robot is now; it must not wait on anything
     * @param ended    told once, with the reason, when the session ends
     */
    void attach(CommandHandler commands, Supplier<ConfigPacket> config, Consumer<String> ended) {
        this.handler = commands;
        this.config = config;
        this.onEnd = ended;
        if (this.ended) {
            ended.accept(endReason);
        }
    }

    private void read() {
        PacketDecoder decoder = new PacketDecoder(new PacketDecoder.Listener() {
            @Override
            public void packet(PioneerPacket packet) {
                take(packet);
            }

            @Override
            public void dropped(String reason) {
                drop(reason);
            }
        });
        byte[] buf = new byte[READ_BYTES];
        String why = "the client closed the connection";
        long started = System.nanoTime();
        InputBudget budget = new InputBudget(started);
        try (InputStream in = socket.getInputStream()) {
            socket.setSoTimeout(CHECK_MS);
            while (!ended) {
                int n;
                try {
                    n = in.read(buf);
                } catch (SocketTimeoutException e) {
                    n = 0;
                }
                if (n < 0) {
                    break;
                }
                if (n > 0) {
                    int before = packetsTaken;
                    decoder.feed(buf, 0, n);
                    long now = System.nanoTime();
                    holdBack(budget.spent(n, packetsTaken - before, now));
                    if (budget.flooding(now)) {
                        why = "it has sent more than " + InputBudget.MAX_PACKETS + " packets or " + InputBudget.MAX_BYTES
                                + " bytes every " + InputBudget.CYCLE_MS + " ms for " + InputBudget.FLOODING_MS + " ms";
                        break;
                    }
                }
                // checked after every read: bytes that never make a packet do not keep a client in
                String late = late(started);
                if (late != null) {
                    why = late;
                    break;
                }
            }
        } catch (IOException e) {
            why = ended ? "closed" : "the connection failed: " + e.getMessage();
        } catch (RuntimeException e) {
            why = "serving it failed: " + e;
            LOG.log(Level.WARNING, "robot " + robot + ": serving the ARIA client at " + client + " failed", e);
        } finally {
            end(why);
        }
    }

    /** Waits out the rest of a cycle in which the client sent more than its budget: it slows only itself. */
    private void holdBack(long nanos) throws InterruptedIOException {
        if (nanos <= 0) {
            return;
        }
        LIMITED.warning("input budgets exceeded by robot " + robot + "'s ARIA clients", () -> "robot " + robot
                + ": the ARIA client at " + client + " sends more than " + InputBudget.MAX_PACKETS + " packets or "
                + InputBudget.MAX_BYTES + " bytes in " + InputBudget.CYCLE_MS + " ms; it is read no faster than that");
        try {
            TimeUnit.NANOSECONDS.sleep(nanos);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted");
        }
    }

    /** Writes the queued packets, on a thread of its own, so that a client that does not read holds back nobody. */
    private void write() {
        try {
            while (!ended) {
                byte[] bytes = outgoing.poll(CHECK_MS, TimeUnit.MILLISECONDS);
                if (bytes != null) {
                    out.write(bytes);
                    if (outgoing.isEmpty()) {
                        out.flush();
                    }
                }
            }
        } catch (IOException e) {
            end("writing to the client failed: " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * A client that holds a port without a handshake is closed so that the port is free for the next.
     *
     * @return why the client is closed, or null while it may stay
     */
    private String late(long started) {
        if (phase != Phase.CONNECTED && System.nanoTime() - started > handshakeMs * 1_000_000L) {
            return "no handshake within " + handshakeMs + " ms";
        }
        return null;
    }

    /**
     * @return whether the client has been silent for longer than it is allowed, longer than a running
     *         ARIA program ever is (it sends a PULSE every 500 ms): the port goes to the next client
     *         that connects, and this one is closed
     */
    boolean isGivingWay() {
        return silentMs() > allowedSilenceMs;
    }

    /** @return how long the client may be silent before it gives way, ms */
    long silenceAllowedMs() {
        return allowedSilenceMs;
    }

    private void take(PioneerPacket p) {
        lastPacketNanos = System.nanoTime();
        heard = true;
        packetsTaken++;
        switch (phase) {
            case SYNC0, SYNC1, SYNC2 -> handshake(p);
            case CONNECTED -> {
                if (handler == null) {
                    return;
                }
                if (p.id() == Commands.OPEN) {
                    opened = true;
                } else if (p.id() == Commands.CONFIG) {
                    send(config.get().toPacket());
                    return;
                }
                handler.handle(p);
            }
            default -> throw new IllegalStateException("no phase " + phase);
        }
    }

    private void handshake(PioneerPacket p) {
        int expected = phase.ordinal();
        if (p.id() == expected) {
            send(expected == Commands.SYNC2 ? identity.toPacket() : PioneerPacket.of(expected));
            phase = Phase.values()[expected + 1];
            if (phase == Phase.CONNECTED) {
                LIMITED.info("handshakes with robot " + robot + "'s ARIA clients", () -> "robot " + robot
                        + ": an ARIA client connected from " + client);
                connected.accept(this);
            }
        } else if (p.id() == Commands.SYNC0) {
            // a client that starts again (ARIA does after a timeout) starts from the first step
            send(PioneerPacket.of(Commands.SYNC0));
            phase = Phase.SYNC1;
        } else {
            drop("packet " + p.id() + " came during the handshake, which expects SYNC" + expected);
        }
    }

    private void drop(String reason) {
        LIMITED.warning("packets dropped from robot " + robot + "'s ARIA clients", () -> "robot " + robot
                + ": dropped from the ARIA client at " + client + ": " + reason);
    }

    /** @return whether a whole packet has come from the client: it has begun the handshake, at least */
    boolean isHeard() {
        return heard;
    }

    /** @return whether the client has sent OPEN: status packets flow */
    boolean isOpen() {
        return opened && !ended;
    }

    /** @return ms since the client's last packet */
    long silentMs() {
        return (System.nanoTime() - lastPacketNanos) / 1_000_000;
    }

    /** @return whether the session has ended */
    boolean isEnded() {
        return ended;
    }

    /** @return where the client connected from */
    String client() {
        return client;
    }

    /**
     * Queues a packet for the client. A client that has let {@value #MAX_QUEUED} packets (some
     * seconds of status and laser packets) pile up unread is closed: it holds back nobody.
     *
     * @param p the packet
     */
    void send(PioneerPacket p) {
        if (ended) {
            return;
        }
        if (!outgoing.offer(p.encode())) {
            end("it has not read the last " + MAX_QUEUED + " packets sent to it");
        }
    }

    /**
     * Ends the session and closes the connection; the first reason is the one logged.
     *
     * @param reason why
     */
    void end(String reason) {
        synchronized (this) {
            if (ended) {
                return;
            }
            endReason = reason;
            ended = true;
        }
        LIMITED.info("departures of robot " + robot + "'s ARIA clients", () -> "robot " + robot + ": the ARIA client at "
                + client + " left: " + reason);
        try {
            socket.close();
        } catch (IOException e) {
            LOG.log(Level.FINE, "closing", e);
        }
        Consumer<String> r = onEnd;
        if (r != null) {
            r.accept(reason);
        }
    }
}
