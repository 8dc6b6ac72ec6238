package robosim.pioneer;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketException;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Predicate;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * A client of a Pioneer robot server (a real Pioneer behind a serial-to-TCP bridge, MobileSim, or
 * RoboSim's Pioneer port), written from the protocol: the SYNC0/1/2 handshake, OPEN, the CONFIG
 * request, commands, and the server's packets read by a thread of the client's own into a bounded
 * queue. {@link #startPulses()} keeps the link alive as ARIA does, with a PULSE whenever nothing has
 * been sent for {@value #PULSE_MS} ms.
 */
public final class PioneerClient implements Closeable {
    private static final Logger LOG = Logger.getLogger(PioneerClient.class.getName());
    /** ARIA sends a PULSE after this long without sending. */
    public static final long PULSE_MS = 500;
    private static final int QUEUE = 4096;
    private static final int SYNC_TRIES = 5;
    private static final long SYNC_WAIT_MS = 1000;

    private final Socket socket;
    private final OutputStream out;
    private final BlockingQueue<PioneerPacket> received = new LinkedBlockingQueue<>(QUEUE);
    /** Queued when the connection ends, so that whoever waits for a packet wakes at once; left for the next. */
    private final PioneerPacket ended = PioneerPacket.of(0);
    private final AtomicLong lastSentNanos = new AtomicLong(System.nanoTime());
    private final String where;
    private volatile boolean closed;
    private volatile String endReason;
    private RobotIdentity identity;
    private Thread pulses;

    private PioneerClient(Socket socket, String where) throws IOException {
        this.socket = socket;
        this.where = where;
        this.out = socket.getOutputStream();
        Thread reader = new Thread(this::read, "pioneer-client-" + where);
        reader.setDaemon(true);
        reader.start();
    }

    /**
     * Connects and does the SYNC0, SYNC1, SYNC2 handshake, each step tried again if unanswered.
     *
     * @param host      the server
     * @param port      its port
     * @param timeoutMs the longest wait to connect, and for each answer
     * @return the client, ready for {@link #open(long)}
     * @throws IOException if the connection fails or the server does not answer the handshake
     */
    public static PioneerClient connect(String host, int port, long timeoutMs) throws IOException {
        Socket socket = new Socket();
        try {
            socket.connect(new InetSocketAddress(host, port), (int) timeoutMs);
            socket.setTcpNoDelay(true);
            PioneerClient c = new PioneerClient(socket, host + ":" + port);
            c.handshake(timeoutMs);
            return c;
        } catch (IOException | RuntimeException e) {
            socket.close();
            throw e;
        }
    }

    private void handshake(long timeoutMs) throws IOException {
        for (int sync = Commands.SYNC0; sync <= Commands.SYNC2; sync++) {
            PioneerPacket answer = null;
            for (int i = 0; i < SYNC_TRIES && answer == null && !closed; i++) {
                try {
                    send(PioneerPacket.of(sync));
                } catch (IOException e) {
                    close();
                    throw new IOException("the robot server at " + where + " closed the connection during the"
                            + " handshake (SYNC" + sync + "): " + e.getMessage(), e);
                }
                int expected = sync;
                answer = await(p -> p.id() == expected, Math.min(timeoutMs, SYNC_WAIT_MS));
            }
            if (answer == null) {
                close();
                throw new IOException("the robot server at " + where + " did not answer SYNC" + sync + " ("
                        + SYNC_TRIES + " tries)" + (endReason == null ? "" : ": " + endReason));
            }
            if (sync == Commands.SYNC2) {
                identity = RobotIdentity.decode(answer);
            }
        }
    }

    /**
     * Sends OPEN, then CONFIG until the configuration reply comes, as ARIA does.
     *
     * @param timeoutMs the longest wait for the reply
     * @return the configuration
     * @throws IOException if no reply comes
     */
    public ConfigPacket open(long timeoutMs) throws IOException {
        send(Commands.com(Commands.OPEN));
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        while (System.nanoTime() < deadline) {
            send(Commands.comInt(Commands.CONFIG, 1));
            PioneerPacket reply = await(p -> p.id() == Commands.CONFIG_PACKET, Math.min(timeoutMs, 500));
            if (reply != null) {
                return ConfigPacket.decode(reply);
            }
        }
        throw new IOException("the robot server at " + where + " sent no CONFIG reply within " + timeoutMs + " ms");
    }

    /** @return the answer to SYNC2 */
    public RobotIdentity identity() {
        return identity;
    }

    /**
     * Sends a packet.
     *
     * @param packet the packet
     * @throws IOException if the connection fails
     */
    public void send(PioneerPacket packet) throws IOException {
        byte[] bytes = packet.encode();
        sendRaw(bytes);
    }

    /**
     * Sends bytes as they are: for tests of how a server takes garbage.
     *
     * @param bytes anything
     * @throws IOException if the connection fails
     */
    public void sendRaw(byte[] bytes) throws IOException {
        synchronized (out) {
            out.write(bytes);
            out.flush();
        }
        lastSentNanos.set(System.nanoTime());
    }

    /**
     * Waits for the next packet the server sends.
     *
     * @param timeoutMs the longest wait
     * @return the packet, or null if none came in time (or the connection ended)
     * @throws InterruptedException if interrupted
     */
    public PioneerPacket receive(long timeoutMs) throws InterruptedException {
        PioneerPacket p = received.poll(timeoutMs, TimeUnit.MILLISECONDS);
        if (p == ended) {
            received.offer(ended);
            return null;
        }
        return p;
    }

    /**
     * Waits for a packet that matches, discarding the others.
     *
     * @param wanted    what to wait for
     * @param timeoutMs the longest wait
     * @return the packet, or null if none came in time
     */
    public PioneerPacket await(Predicate<PioneerPacket> wanted, long timeoutMs) {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        try {
            long left;
            while ((left = deadline - System.nanoTime()) > 0) {
                PioneerPacket p = received.poll(left, TimeUnit.NANOSECONDS);
                if (p == ended) {
                    received.offer(ended);
                    return null;
                }
                if (p != null && wanted.test(p)) {
                    return p;
                }
                if (p == null && closed) {
                    return null;
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return null;
    }

    /**
     * Waits for the next SIP.
     *
     * @param timeoutMs the longest wait
     * @return it, or null if none came in time
     */
    public Sip nextSip(long timeoutMs) {
        PioneerPacket p = await(q -> q.id() == Commands.SIP_STOPPED || q.id() == Commands.SIP_MOVING, timeoutMs);
        return p == null ? null : Sip.decode(p);
    }

    /** Sends a PULSE whenever nothing has been sent for {@value #PULSE_MS} ms, until closed. */
    public synchronized void startPulses() {
        if (pulses != null) {
            return;
        }
        pulses = new Thread(() -> {
            while (!closed) {
                try {
                    Thread.sleep(PULSE_MS / 5);
                    if (System.nanoTime() - lastSentNanos.get() >= TimeUnit.MILLISECONDS.toNanos(PULSE_MS)) {
                        send(Commands.com(Commands.PULSE));
                    }
                } catch (InterruptedException e) {
                    return;
                } catch (IOException e) {
                    return;
                }
            }
        }, "pioneer-pulse-" + where);
        pulses.setDaemon(true);
        pulses.start();
    }

    /** @return whether the connection has ended */
    public boolean isClosed() {
        return closed;
    }

    /** @return why the connection ended, or null while it lasts */
    public String endReason() {
        return endReason;
    }

    /** @return the server, {@code host:port} */
    public String server() {
        return where;
    }

    private void read() {
        PacketDecoder decoder = new PacketDecoder(new PacketDecoder.Listener() {
            @Override
            public void packet(PioneerPacket packet) {
                while (!received.offer(packet)) {
                    received.poll(); // the oldest goes: nobody took it in time
                }
            }

            @Override
            public void dropped(String reason) {
                LOG.fine(() -> "from " + where + ": " + reason);
            }
        });
        byte[] buf = new byte[4096];
        try (InputStream in = socket.getInputStream()) {
            int n;
            while ((n = in.read(buf)) > 0) {
                decoder.feed(buf, 0, n);
            }
            endReason = "the server closed the connection";
        } catch (SocketException e) {
            endReason = closed ? "closed" : "the connection failed: " + e.getMessage();
        } catch (IOException e) {
            endReason = "the connection failed: " + e.getMessage();
        } finally {
            closed = true;
            wakeWaiters();
        }
    }

    private void wakeWaiters() {
        while (!received.offer(ended)) {
            received.poll();
        }
    }

    /** Says goodbye as ARIA does (ENABLE 0, CLOSE), then closes. */
    public void disconnect() {
        try {
            send(Commands.comInt(Commands.ENABLE, 0));
            send(Commands.com(Commands.CLOSE));
        } catch (IOException e) {
            LOG.log(Level.FINE, "goodbye not sent to " + where, e);
        }
        close();
    }

    /** Closes the connection without a word. */
    @Override
    public void close() {
        closed = true;
        wakeWaiters();
        try {
            socket.close();
        } catch (IOException e) {
            LOG.log(Level.FINE, "closing " + where, e);
        }
        Thread p = pulses;
        if (p != null) {
            p.interrupt();
        }
    }
}
