package robosim.pioneer.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.hw.HardwareOptions;
import robosim.pioneer.Commands;
import robosim.pioneer.PioneerClient;
import robosim.protocol.CapturedLog;

/**
 * A flood of connections to a Pioneer port is refused as fast as it comes, with a log line a second,
 * and a client that comes after it gets in at once: with a client on the port, and without one.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class PioneerPortFloodTest {
    private static final int FLOOD = 400;
    private static final int ARIA_REPLY_MS = PioneerPortHandshakeTest.ARIA_REPLY_MS;

    private final List<Socket> flood = new ArrayList<>();
    private CapturedLog log;
    private final long testStarted = System.nanoTime();
    private SilentEnvironment env;
    private PioneerPorts ports;

    @BeforeEach
    void open() throws IOException {
        log = new CapturedLog("robosim.pioneer.server");
        env = new SilentEnvironment();
        HardwareOptions patient = new HardwareOptions(120_000, HardwareOptions.DEFAULT_LOST_AFTER_MS, 5_000);
        ports = PioneerPorts.open(List.of(SilentEnvironment.robot(100)), new PioneerPortOptions("127.0.0.1", 0, false,
                PioneerPortOptions.DEFAULT_WATCHDOG_MS, true, patient), "127.0.0.1", env.port(), null, code -> { });
    }

    @AfterEach
    void close() throws IOException {
        log.close();
        for (Socket s : flood) {
            s.close();
        }
        ports.close();
        env.close();
    }

    /** Opens the flood's connections, each saying nothing. */
    private void openFlood() throws IOException {
        for (int i = 0; i < FLOOD; i++) {
            Socket s = new Socket();
            s.connect(new InetSocketAddress("127.0.0.1", ports.portOf("r1")), 5000);
            flood.add(s);
        }
    }

    /** @return how many of the flood's connections the port has closed, each waited for at most 10 s */
    private int closedByThePort() throws IOException {
        int closed = 0;
        for (Socket s : flood) {
            s.setSoTimeout(10_000);
            try {
                if (s.getInputStream().read() < 0) {
                    closed++;
                }
            } catch (SocketTimeoutException stillOpen) {
                // counted as not closed
            } catch (IOException reset) {
                closed++;
            }
        }
        return closed;
    }

    private List<String> lines() {
        return log.lines();
    }

    @Test
    void withAClientOnThePortEveryConnectionOfAFloodIsRefusedAndTheNextClientGetsInOnceItLeaves() throws Exception {
        try (PioneerClient first = PioneerClient.connect("127.0.0.1", ports.portOf("r1"), ARIA_REPLY_MS)) {
            first.open(ARIA_REPLY_MS);
            first.startPulses();
            long started = System.nanoTime();
            openFlood();
            System.out.println("opened after " + TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started));
            assertEquals(FLOOD, closedByThePort(), "every connection of the flood is refused");
            long ms = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
            System.out.println("opening and refusing " + FLOOD + " connections took " + ms + " ms");
            assertFalse(first.isClosed(), "the client on the port stays");
            assertTrue(first.nextSip(8000) != null, "and is sent its status");
            first.send(Commands.com(Commands.CLOSE));
        }
        try (PioneerClient next = PioneerClient.connect("127.0.0.1", ports.portOf("r1"), ARIA_REPLY_MS)) {
            assertEquals("SIM", next.open(ARIA_REPLY_MS).serial(), "the next client gets the port");
        }
        long seconds = TimeUnit.NANOSECONDS.toSeconds(System.nanoTime() - testStarted) + 1;
        long refusals = lines().stream().filter(l -> l.contains("has a client already")).count();
        assertTrue(refusals >= 1 && refusals <= seconds, "a line a second (" + seconds + " s), not one a connection: "
                + lines());
    }

    @Test
    void withoutAClientAFloodOfSilentConnectionsHoldsNothingAndTheNextClientGetsIn() throws Exception {
        openFlood();
        try (PioneerClient next = PioneerClient.connect("127.0.0.1", ports.portOf("r1"), ARIA_REPLY_MS)) {
            assertEquals("SIM", next.open(ARIA_REPLY_MS).serial(), "a client after the flood gets the port at once");
            assertEquals(FLOOD, closedByThePort(), "each silent connection gave way to the next");
            assertFalse(next.isClosed());
        }
        long seconds = TimeUnit.NANOSECONDS.toSeconds(System.nanoTime() - testStarted) + 1;
        long departures = lines().stream().filter(l -> l.contains("left: it sent nothing")).count();
        assertTrue(departures >= 1 && departures <= seconds, "a line a second (" + seconds + " s), not one a connection: "
                + lines());
    }

    @Test
    void aClientThatSaysCloseAndConnectsAgainAtOnceGetsThePort() throws Exception {
        for (int i = 0; i < 20; i++) {
            try (PioneerClient c = PioneerClient.connect("127.0.0.1", ports.portOf("r1"), ARIA_REPLY_MS)) {
                c.open(ARIA_REPLY_MS);
                c.send(Commands.com(Commands.CLOSE));
            }
        }
    }
}
