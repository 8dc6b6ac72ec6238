package robosim.pioneer.server;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.pioneer.PioneerPacket;
import robosim.pioneer.RobotIdentity;
import robosim.params.ConversionFactors;
import robosim.protocol.Await;
import robosim.protocol.RobotParameters;

/** A session against clients that misbehave: they must not hold a port or the robot's thread. */
@Timeout(value = 1, unit = TimeUnit.MINUTES)
class PioneerSessionTest {
    private ServerSocket server;
    private Socket client;
    private Socket accepted;

    /** The handshake time of these sessions, ms: shorter than a port's, for a test that waits it out. */
    private static final long HANDSHAKE_MS = 2_000;

    private PioneerSession session() throws Exception {
        server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        client = new Socket();
        client.setReceiveBufferSize(1024);
        client.connect(server.getLocalSocketAddress());
        accepted = server.accept();
        accepted.setSendBufferSize(1024);
        return new PioneerSession(accepted, "r1", new RobotIdentity("r1", "Pioneer", "p3dx"), HANDSHAKE_MS,
                PioneerPortOptions.DEFAULT_SILENT_MS);
    }

    @AfterEach
    void close() throws Exception {
        for (AutoCloseable c : new AutoCloseable[] {client, accepted, server}) {
            if (c != null) {
                c.close();
            }
        }
    }

    private static boolean endsWithin(PioneerSession s, long ms) {
        return Await.within(Duration.ofMillis(ms), s::isEnded);
    }

    @Test
    void aClientThatDoesNotReadIsClosedWithoutHoldingTheSender() throws Exception {
        PioneerSession s = session();
        s.start(x -> { });
        PioneerPacket big = new PioneerPacket(0x32, new byte[200]);
        long start = System.nanoTime();
        for (int i = 0; i < 20_000 && !s.isEnded(); i++) {
            s.send(big);
        }
        long ms = (System.nanoTime() - start) / 1_000_000;
        assertTrue(endsWithin(s, 5000), "the session ends when its queue is full");
        assertTrue(ms < 5000, "sending never waited on the client: " + ms + " ms");
    }

    @Test
    void bytesThatNeverMakeAPacketDoNotKeepAClientPastTheHandshakeTime() throws Exception {
        PioneerSession s = session();
        s.start(x -> { });
        OutputStream out = client.getOutputStream();
        long start = System.nanoTime();
        while (!s.isEnded() && System.nanoTime() - start < TimeUnit.MILLISECONDS.toNanos(HANDSHAKE_MS + 5000)) {
            out.write(0);
            out.flush();
            Thread.sleep(400); // a peer that trickles: never silent, never a packet; its pace is the point
        }
        assertTrue(s.isEnded(), "closed after the handshake time");
        assertTrue(System.nanoTime() - start >= TimeUnit.MILLISECONDS.toNanos(HANDSHAKE_MS - 100));
    }

    @Test
    void aFailureWhileServingEndsTheSessionSoThePortIsFreeAgain() throws Exception {
        PioneerSession s = session();
        s.start(x -> {
            throw new IllegalStateException("boom");
        });
        OutputStream out = client.getOutputStream();
        for (int sync = 0; sync < 3; sync++) {
            out.write(PioneerPacket.of(sync).encode());
        }
        out.flush();
        assertTrue(endsWithin(s, 5000));
    }

    @Test
    void namesTooLongForAriasPacketsAreRefusedWhenThePortOpens() {
        RobotParameters p = new RobotParameters("Pioneer", "p".repeat(100), 250, 425, 210, 301, 2200, 500, 300, 300, 100,
                100, 0.0056, 5000, List.of());
        ServedRobot r = new ServedRobot("r".repeat(64), "pioneer", p, ConversionFactors.ARIA_DEFAULTS, 100);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> PioneerPort.requireFits(r));
        assertTrue(e.getMessage().contains("too long for the Pioneer protocol's 200-byte packets"), e.getMessage());
        ServedRobot ok = new ServedRobot("r1", "pioneer", new RobotParameters("Pioneer", "p3dx", 250, 425, 210, 301,
                2200, 500, 300, 300, 100, 100, 0.0056, 5000, List.of()), ConversionFactors.ARIA_DEFAULTS, 100);
        PioneerPort.requireFits(ok);
    }
}
