package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Bye;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;

/** One peer's connection on the step loop's selector, over a real loopback socket. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ConnectionTest {
    /** Far more than the loopback socket's buffers hold, so most of it waits in the queue. */
    private static final int FRAMES = 40;
    private static final String REASON = "x".repeat(200_000);

    private Loopback loopback;
    private LogLines log;
    private ExecutorService reader;

    @BeforeEach
    void open() throws IOException {
        loopback = new Loopback();
        log = new LogLines();
        reader = Executors.newSingleThreadExecutor();
    }

    @AfterEach
    void close() throws IOException, InterruptedException {
        log.close();
        loopback.close();
        reader.shutdownNow();
        assertTrue(reader.awaitTermination(10, TimeUnit.SECONDS));
    }

    /** The peer reads, on a thread of its own, up to {@code count} messages or until the stream ends. */
    private CompletableFuture<List<Message>> read(Peer peer, int count) {
        return CompletableFuture.supplyAsync(() -> {
            List<Message> got = new ArrayList<>();
            try {
                while (got.size() < count) {
                    Message m = peer.read();
                    if (m == null) {
                        break;
                    }
                    got.add(m);
                }
            } catch (IOException e) {
                throw new IllegalStateException("after " + got.size() + " messages", e);
            }
            return got;
        }, reader);
    }

    private static Bye numbered(int i) {
        return new Bye(i + REASON);
    }

    @Test
    void framesQueuedWhileThePeerIsNotReadingArriveWholeAndInOrder() throws Exception {
        Peer peer = loopback.connect(Connection.Kind.VIEWER, 64L << 20, 1 << 16);
        Connection c = peer.connection;
        for (int i = 0; i < FRAMES; i++) {
            c.send(numbered(i));
        }

        CompletableFuture<List<Message>> received = read(peer, FRAMES);
        loopback.pumpUntil(received::isDone);

        List<Message> got = received.get();
        assertEquals(FRAMES, got.size());
        for (int i = 0; i < FRAMES; i++) {
            assertEquals(numbered(i), got.get(i));
        }
        assertFalse(c.isClosed());
    }

    @Test
    void aPeerThatFallsBehindBeyondTheLimitIsClosedNamingItAndTheLimit() throws IOException {
        Peer peer = loopback.connect(Connection.Kind.VIEWER, 1 << 20, 1 << 16);
        Connection c = peer.connection;
        ByteBuffer frame = FrameWriter.frame(loopback.codec, numbered(0));

        for (int i = 0; i < 1000 && !c.isClosed(); i++) {
            c.sendFrame(frame.duplicate());
        }

        assertTrue(c.isClosed(), "the queue never passed its limit");
        assertTrue(peer.closedByEnvironment());
        List<String> warnings = log.warnings();
        assertEquals(1, warnings.size(), warnings.toString());
        assertTrue(Pattern.matches("closing viewer at /127\\.0\\.0\\.1:\\d+: it fell \\d+ bytes behind"
                + " \\(the limit is 1048576\\)", warnings.get(0)), warnings.get(0));
    }

    @Test
    void sendAndCloseWritesWhatIsQueuedBeforeClosing() throws Exception {
        Peer peer = loopback.connect(Connection.Kind.ROBOT, 64L << 20, 1 << 16);
        Connection c = peer.connection;
        for (int i = 0; i < FRAMES; i++) {
            c.send(numbered(i));
        }

        c.sendAndClose(new Bye("goodbye"));

        assertFalse(c.isClosed(), "closed before the queue was written");
        c.send(new Bye("too late"));
        CompletableFuture<List<Message>> received = read(peer, Integer.MAX_VALUE);
        loopback.pumpUntil(c::isClosed);
        List<Message> got = received.get(Loopback.WAIT_MS, TimeUnit.MILLISECONDS);
        assertEquals(FRAMES + 1, got.size(), "every frame, the last message, then the end of the stream");
        assertEquals(new Bye("goodbye"), got.get(FRAMES));
        assertEquals(List.of(), log.warnings());
    }

    @Test
    void sendAndCloseWithNothingQueuedClosesAtOnce() throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);

        peer.connection.sendAndClose(new Bye("refused: the run has started"));

        assertTrue(peer.connection.isClosed());
        assertEquals(new Bye("refused: the run has started"), peer.read());
        assertNull(peer.read());
    }

    @Test
    void aCleanEndOfTheStreamReadsAsNull() throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);

        peer.close();

        assertNull(loopback.receive(peer.connection));
    }

    @Test
    void theStreamEndingInsideAFrameIsAnError() throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);

        peer.sendRaw(new byte[] {0, 0, 0, 9, 1, 2});
        peer.close();

        IOException e = assertThrows(IOException.class, () -> loopback.receive(peer.connection));

        assertEquals("the stream ended inside a frame", e.getMessage());
    }

    @Test
    void aPeerIsNamedByItsAddressUntilItSaysWhoItIs() throws IOException {
        Connection c = loopback.connect(Connection.Kind.ROBOT).connection;
        assertTrue(c.peer().startsWith("robot at /127.0.0.1:"), c.peer());

        c.setName("r1");

        assertEquals("robot r1", c.peer());
    }

    @Test
    void closeLogsOneLineAndClosesOnce() throws IOException {
        Peer peer = loopback.connect(Connection.Kind.ROBOT);
        peer.connection.setName("r1");

        peer.connection.close("it did not send its requests for step 3 within 2000 ms");
        peer.connection.close("again");

        assertTrue(peer.closedByEnvironment());
        assertEquals(List.of("closing robot r1: it did not send its requests for step 3 within 2000 ms"),
                log.warnings());
    }
}
