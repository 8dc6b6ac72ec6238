package robosim.pioneer.server;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.util.function.Supplier;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.pioneer.Commands;
import robosim.pioneer.ConfigPacket;
import robosim.pioneer.PioneerPacket;
import robosim.pioneer.PacketDecoder;
import robosim.pioneer.RobotIdentity;

/**
 * One ARIA client's connection to a robot's Pioneer port: the SYNC0, SYNC1, SYNC2 handshake, then
 * the client's commands handed to the robot's {@link CommandHandler}, and the robot's packets
 * written back. The client's bytes are read by a thread of the session's own; garbage, bad lengths
 * and bad checksums are dropped with a log line (at most one a second, with a count), never ending
 * the session or the run.
 */
final class PioneerSession {
    private static final Logger LOG = Logger.getLogger(PioneerSession.class.getName());

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
    private CommandHandler handler;
    private Supplier<ConfigPacket> config;
    private Runnable onEnd;
    private long drops;
    private long lastDropLogNanos;

    /**
     * @param socket   the client's connection
     * @param robot    the robot's name, for log lines
     * @param identity what SYNC2 answers
     */
    PioneerSession(Socket socket, String robot, RobotIdentity identity) throws IOException {
        this.socket = socket;
        this.out = socket.getOutputStream();
        this.client = socket.getRemoteSocketAddress().toString();
        this.robot = robot;
        this.identity = identity;
    }

    /**
     * Starts reading the client's packets.
     *
     * @param commands carries out the commands after the handshake
     * @param config   the answer to CONFIG, as the robot is now
     * @param ended    run once when the session ends
     */
    void start(CommandHandler commands, Supplier<ConfigPacket> config, Runnable ended) {
        this.handler = commands;
        this.config = config;
        this.onEnd = ended;
        Thread t = new Thread(this::read, "pioneer-" + robot);
        t.setDaemon(true);
        t.start();
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
        byte[] buf = new byte[4096];
        String why = "the client closed the connection";
        try (InputStream in = socket.getInputStream()) {
            int n;
            while (!ended && (n = in.read(buf)) > 0) {
                decoder.feed(buf, 0, n);
            }
        } catch (IOException e) {
            why = ended ? "closed" : "the connection failed: " + e.getMessage();
        }
        end(why);
    }

    private void take(PioneerPacket p) {
        lastPacketNanos = System.nanoTime();
        switch (phase) {
            case SYNC0, SYNC1, SYNC2 -> handshake(p);
            case CONNECTED -> {
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
                LOG.info(() -> "robot " + robot + ": an ARIA client connected from " + client);
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
        drops++;
        long now = System.nanoTime();
        if (now - lastDropLogNanos > 1_000_000_000L) {
            long n = drops;
            drops = 0;
            lastDropLogNanos = now;
            LOG.warning(() -> "robot " + robot + ": dropped from the ARIA client at " + client + ": " + reason
                    + (n > 1 ? " (and " + (n - 1) + " more drops since the last line)" : ""));
        }
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
     * Writes a packet; a failure ends the session.
     *
     * @param p the packet
     */
    void send(PioneerPacket p) {
        if (ended) {
            return;
        }
        try {
            synchronized (out) {
                out.write(p.encode());
                out.flush();
            }
        } catch (IOException e) {
            end("writing to the client failed: " + e.getMessage());
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
            ended = true;
        }
        LOG.info(() -> "robot " + robot + ": the ARIA client at " + client + " left: " + reason);
        try {
            socket.close();
        } catch (IOException e) {
            LOG.log(Level.FINE, "closing", e);
        }
        if (onEnd != null) {
            onEnd.run();
        }
    }
}
