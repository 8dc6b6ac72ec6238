package robosim.it;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.Locale;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import robosim.pioneer.Commands;
import robosim.pioneer.ConfigPacket;
import robosim.pioneer.PacketDecoder;
import robosim.pioneer.PioneerPacket;
import robosim.pioneer.RobotIdentity;
import robosim.pioneer.Sip;

/**
 * Connects to a Pioneer port as an ARIA program does, with ARIA's own patience, and fails where ARIA
 * would give up: AriaCoda's {@code ArRobot::blockingConnect} and {@code asyncConnectHandler} (SYNC0,
 * SYNC1, SYNC2, each answer awaited {@value #SYNC_REPLY_MS} ms; "no robot responding" after more than
 * {@value #NO_REPLY_LIMIT} unanswered, or more than {@value #RETRIES} when every try went unanswered;
 * a {@value #CYCLE_MS} ms cycle, OPEN, then CONFIG again every {@value #CONFIG_RESEND_MS} ms
 * ({@code ArRobotConfigPacketReader}) until the reply comes, for at most {@value #CONFIG_MS} ms after
 * OPEN), then BATTERYINFO as ARIA's battery reader sends it. ARIA without the CONFIG reply goes on,
 * but without the serial number "SIM" that tells it the robot is simulated (AriaCoda's laserConnect
 * then opens /dev/ttyS2): here that is a failure. After the handshake a status packet must come
 * within ARIA's {@value #ODOMETRY_TIMEOUT_MS} ms each time, and a PULSE goes out every
 * {@value #PULSE_MS} ms.
 *
 * <p>Also a program: {@code AriaHandshakeClient HOST PORT [SIPS]} connects, reads SIPS status packets
 * (10 unless given), prints what it learned, and exits 0; 1 where ARIA would have failed; 2 on bad
 * arguments.
 */
public final class AriaHandshakeClient implements Closeable {
    /** How long ARIA waits for each SYNC answer, ms. */
    public static final int SYNC_REPLY_MS = 1000;
    /** How long after OPEN ARIA waits for the CONFIG reply, ms. */
    public static final int CONFIG_MS = 1000;
    /** How often ARIA asks for CONFIG again while waiting, ms. */
    public static final int CONFIG_RESEND_MS = 200;
    /** ARIA's robot cycle, ms; its connect loop sleeps 80 % of it between tries. */
    public static final int CYCLE_MS = 100;
    /** How long ARIA waits for odometry before it drops the robot, ms. */
    public static final int ODOMETRY_TIMEOUT_MS = 8000;
    /** ARIA gives up after more unanswered SYNCs than this, when every try went unanswered. */
    public static final int RETRIES = 5;
    /** ARIA gives up after more unanswered SYNCs than this in any case. */
    public static final int NO_REPLY_LIMIT = 10;
    /** A PULSE goes out this often, ms. */
    public static final int PULSE_MS = 500;

    /**
     * What the handshake learnt.
     *
     * @param identity the SYNC2 answer: name, class, subclass
     * @param config   the CONFIG reply
     * @param configMs ms from OPEN to the CONFIG reply
     */
    public record Handshake(RobotIdentity identity, ConfigPacket config, long configMs) { }

    private final Socket socket;
    private final OutputStream out;
    private final BlockingQueue<PioneerPacket> received = new LinkedBlockingQueue<>();
    private volatile String endReason;
    private long lastSent = System.nanoTime();
    private Handshake handshake;

    private AriaHandshakeClient(Socket socket) throws IOException {
        this.socket = socket;
        this.out = socket.getOutputStream();
        Thread reader = new Thread(this::read, "aria-handshake-" + socket.getPort());
        reader.setDaemon(true);
        reader.start();
    }

    /**
     * Connects and does ARIA's handshake.
     *
     * @param host the Pioneer port's host
     * @param port the port
     * @return the client, connected
     * @throws IOException saying where ARIA would have given up
     */
    public static AriaHandshakeClient connect(String host, int port) throws IOException {
        Socket s = new Socket();
        try {
            s.connect(new InetSocketAddress(host, port), ODOMETRY_TIMEOUT_MS);
            s.setTcpNoDelay(true);
            AriaHandshakeClient c = new AriaHandshakeClient(s);
            c.handshake = c.shake();
            return c;
        } catch (IOException | RuntimeException e) {
            s.close();
            throw e;
        }
    }

    /** @return what the handshake learnt */
    public Handshake handshake() {
        return handshake;
    }

    private Handshake shake() throws IOException {
        int state = 0;
        int tries = 0;
        int unanswered = 0;
        PioneerPacket answer = null;
        while (state < 3) {
            if (++tries > 50) {
                throw new IOException("Could not connect: 50 SYNC tries without the handshake (as ARIA gives up)");
            }
            send(PioneerPacket.of(state));
            answer = receive(SYNC_REPLY_MS);
            if (answer == null) {
                unanswered++;
                if (unanswered > RETRIES && unanswered >= tries || unanswered > NO_REPLY_LIMIT) {
                    throw new IOException("Could not connect, no robot responding (" + unanswered
                            + " SYNCs unanswered within " + SYNC_REPLY_MS + " ms" + ended() + ")");
                }
                state = 0;
            } else {
                state = answer.id() == state ? state + 1 : 0;
            }
            if (state < 3) {
                pause(CYCLE_MS * 8 / 10);
            }
        }
        RobotIdentity identity = RobotIdentity.decode(answer);
        pause(CYCLE_MS);
        send(Commands.comInt(Commands.OPEN, 1));
        long opened = System.nanoTime();
        long resend = TimeUnit.MILLISECONDS.toNanos(CONFIG_RESEND_MS);
        long limit = TimeUnit.MILLISECONDS.toNanos(CONFIG_MS);
        long asked = opened - resend;
        while (true) {
            long now = System.nanoTime();
            if (now - asked >= resend) {
                send(Commands.comInt(Commands.CONFIG, 1));
                asked = now;
            }
            // what comes until CONFIG is due again, or the wait is over
            long waitNanos = Math.max(0, Math.min(asked + resend - now, opened + limit - now));
            for (PioneerPacket p = receive(TimeUnit.NANOSECONDS.toMillis(waitNanos) + 1); p != null; p = receive(0)) {
                if (p.id() == Commands.CONFIG_PACKET) {
                    send(Commands.comInt(Commands.BATTERYINFO, 1));
                    return new Handshake(identity, ConfigPacket.decode(p),
                            TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - opened));
                }
            }
            if (System.nanoTime() - opened > limit) {
                throw new IOException("no CONFIG reply within " + CONFIG_MS + " ms of OPEN: ARIA goes on without the"
                        + " robot's serial number, so it does not know the robot is simulated" + ended());
            }
        }
    }

    /**
     * Waits for the next status packet as ARIA does, with a PULSE whenever {@value #PULSE_MS} ms
     * have passed without sending.
     *
     * @return the SIP
     * @throws IOException if none comes within {@value #ODOMETRY_TIMEOUT_MS} ms, as ARIA then drops the robot
     */
    public Sip nextSip() throws IOException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ODOMETRY_TIMEOUT_MS);
        while (System.nanoTime() < deadline) {
            if (System.nanoTime() - lastSent >= TimeUnit.MILLISECONDS.toNanos(PULSE_MS)) {
                send(Commands.com(Commands.PULSE));
            }
            PioneerPacket p = receive(CYCLE_MS);
            if (p != null && (p.id() == Commands.SIP_STOPPED || p.id() == Commands.SIP_MOVING)) {
                return Sip.decode(p);
            }
        }
        throw new IOException("Losing connection because no odometry received from robot in "
                + ODOMETRY_TIMEOUT_MS + " milliseconds" + ended());
    }

    /**
     * Sends a command, as ARIA's {@code com} calls do.
     *
     * @param p the command
     * @throws IOException if the connection fails
     */
    public synchronized void send(PioneerPacket p) throws IOException {
        out.write(p.encode());
        out.flush();
        lastSent = System.nanoTime();
    }

    private PioneerPacket receive(long ms) throws IOException {
        try {
            return received.poll(ms, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
    }

    /** ARIA's pace between its connect tries: the peer's timing is what the port under test must take. */
    private static void pause(long ms) throws IOException {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
    }

    private String ended() {
        String why = endReason;
        return why == null ? "" : "; the connection ended: " + why;
    }

    private void read() {
        PacketDecoder decoder = new PacketDecoder(new PacketDecoder.Listener() {
            @Override
            public void packet(PioneerPacket packet) {
                received.add(packet);
            }

            @Override
            public void dropped(String reason) {
                // ARIA drops bad packets silently too
            }
        });
        byte[] buf = new byte[4096];
        try (InputStream in = socket.getInputStream()) {
            int n;
            while ((n = in.read(buf)) >= 0) {
                decoder.feed(buf, 0, n);
            }
            endReason = "the server closed it";
        } catch (IOException e) {
            endReason = e.getMessage();
        }
    }

    /** Leaves as ARIA's {@code ArRobot::disconnect} does: ENABLE 0, CLOSE, then the connection closes. */
    @Override
    public void close() throws IOException {
        try {
            if (!socket.isClosed()) {
                send(Commands.comInt(Commands.ENABLE, 0));
                send(Commands.comInt(Commands.CLOSE, 1));
            }
        } catch (IOException e) {
            // the server went first: nothing to say goodbye to
        } finally {
            socket.close();
        }
    }

    /**
     * Connects, reads status packets and prints what it learnt.
     *
     * @param args HOST PORT [SIPS]
     */
    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    /**
     * {@link #main}'s work, with its exit code.
     *
     * @param args HOST PORT [SIPS]
     * @param out  where what it learnt goes
     * @param err  where the failure goes
     * @return 0 connected and read the SIPs; 1 ARIA would have failed; 2 bad arguments
     */
    static int run(String[] args, PrintStream out, PrintStream err) {
        int port;
        int sips;
        try {
            if (args.length < 2 || args.length > 3) {
                throw new IllegalArgumentException("expected HOST PORT [SIPS], got " + args.length + " arguments");
            }
            port = Integer.parseInt(args[1]);
            sips = args.length == 3 ? Integer.parseInt(args[2]) : 10;
            if (port < 1 || port > 65535 || sips < 0) {
                throw new IllegalArgumentException("port " + port + " must be 1 to 65535 and SIPS " + sips
                        + " at least 0");
            }
        } catch (IllegalArgumentException e) {
            err.println("usage: AriaHandshakeClient HOST PORT [SIPS]: " + e.getMessage());
            return 2;
        }
        try (AriaHandshakeClient c = connect(args[0], port)) {
            Handshake h = c.handshake();
            out.printf(Locale.ROOT, "Name: %s%nType: %s%nSubtype: %s%nRobot Serial Number: %s%n", h.identity().name(),
                    h.identity().robotClass(), h.identity().subclass(), h.config().serial());
            out.printf(Locale.ROOT, "CONFIG reply %d ms after OPEN; SIP cycle %d ms%n", h.configMs(), h.config().sipCycle());
            Sip last = null;
            for (int i = 0; i < sips; i++) {
                last = c.nextSip();
            }
            if (last != null) {
                out.printf(Locale.ROOT, "%d SIPs; the last: x %d, y %d, th %d, wheels %d %d%n", sips, last.xPos(),
                        last.yPos(), last.th(), last.leftVel(), last.rightVel());
            }
            return 0;
        } catch (IOException e) {
            err.println("AriaHandshakeClient: " + args[0] + ":" + port + ": " + e.getMessage());
            return 1;
        }
    }
}
