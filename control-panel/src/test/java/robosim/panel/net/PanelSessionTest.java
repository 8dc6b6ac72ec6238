package robosim.panel.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.panel.model.Request;
import robosim.protocol.ControlReply;
import robosim.protocol.RunStatus;

@Timeout(value = 60, unit = TimeUnit.SECONDS)
class PanelSessionTest {
    @Test
    void aRequestIsAnsweredWithTheEnvironmentsReply() throws Exception {
        try (FakeEnvironment env = new FakeEnvironment();
             PanelSession s = new PanelSession("127.0.0.1", env.port(), null)) {
            ControlReply r = s.send(Request.pause()).get(10, TimeUnit.SECONDS);

            assertEquals("did pause", r.text());
            assertEquals(List.of("pause"), env.requests);
        }
    }

    @Test
    void statusesKeepComingWhileALongStepWaitsForItsAnswer() throws Exception {
        BlockingQueue<RunStatus> statuses = new LinkedBlockingQueue<>();
        try (FakeEnvironment env = new FakeEnvironment();
             PanelSession s = new PanelSession("127.0.0.1", env.port(), null)) {
            CompletableFuture<ControlReply> step = s.send(Request.step("1000"));
            s.poll(50, statuses::add, line -> { }, why -> { });

            RunStatus first = statuses.poll(10, TimeUnit.SECONDS);
            RunStatus second = statuses.poll(10, TimeUnit.SECONDS);

            assertEquals("fake", first.world());
            assertEquals("fake", second.world());
            assertFalse(step.isDone(), "the step is still held");
            env.release.countDown();
            assertEquals("did step", step.get(10, TimeUnit.SECONDS).text());
            assertEquals(List.of("control-panel", "control-panel-status"), env.hellos.stream().sorted().toList());
        }
    }

    @Test
    void theEnvironmentsLogLinesComeWithTheStatusesOnceFollowed() throws Exception {
        BlockingQueue<String> lines = new LinkedBlockingQueue<>();
        BlockingQueue<RunStatus> statuses = new LinkedBlockingQueue<>();
        try (FakeEnvironment env = new FakeEnvironment();
             PanelSession s = new PanelSession("127.0.0.1", env.port(), null)) {
            s.followLog(lines::add);
            s.poll(50, statuses::add, line -> { }, why -> { });

            assertEquals("[step 1] robot r1 connected", lines.poll(10, TimeUnit.SECONDS));
            assertEquals("[step 1] WARNING: closing robot r2: it disconnected", lines.poll(10, TimeUnit.SECONDS));
            assertEquals("fake", statuses.poll(10, TimeUnit.SECONDS).world());
            assertEquals(List.of("log"), env.requests);
        }
    }

    @Test
    void anEnvironmentThatIsGoneFailsTheRequestSayingWhich() throws Exception {
        int port;
        try (FakeEnvironment env = new FakeEnvironment()) {
            port = env.port();
        }
        try (PanelSession s = new PanelSession("127.0.0.1", port, null)) {
            ExecutionException e = assertThrows(ExecutionException.class,
                    () -> s.send(Request.resume()).get(20, TimeUnit.SECONDS));

            IOException cause = assertInstanceOf(IOException.class, e.getCause());
            assertTrue(cause.getMessage().startsWith("resume: "), cause.getMessage());
        }
    }

    private static final String SECRET = "the-run-secret-0123456789";

    @Test
    void aPanelAttachedBeforeTheSecretIsWrittenPicksItUpOnceItIsThere() throws Exception {
        AtomicReference<String> written = new AtomicReference<>();
        BlockingQueue<RunStatus> statuses = new LinkedBlockingQueue<>();
        BlockingQueue<String> lines = new LinkedBlockingQueue<>();
        List<String> log = new CopyOnWriteArrayList<>();
        try (FakeEnvironment env = new FakeEnvironment(SECRET);
             PanelSession s = PanelSession.withSecrets("127.0.0.1", env.port(), written::get)) {
            s.poll(50, statuses::add, lines::add, log::add);

            assertTrue(lines.poll(10, TimeUnit.SECONDS).startsWith("waiting for the run secret of 127.0.0.1:"));
            written.set(SECRET);

            assertEquals("fake", statuses.poll(10, TimeUnit.SECONDS).world());
            assertEquals(1, log.size(), "one line for the wait, none per attempt: " + log);
            assertTrue(log.get(0).contains("presented no run secret"), log.get(0));
        }
    }

    @Test
    void aFinalRefusalIsSaidOnceAndRetriedOnlyRarely() throws Exception {
        BlockingQueue<String> lines = new LinkedBlockingQueue<>();
        List<String> log = new CopyOnWriteArrayList<>();
        try (FakeEnvironment env = new FakeEnvironment(SECRET);
             PanelSession s = PanelSession.withSecrets("127.0.0.1", env.port(), () -> "an-old-runs-secret-0123")) {
            s.poll(50, st -> { }, lines::add, log::add);

            String line = lines.poll(10, TimeUnit.SECONDS);
            assertEquals("refused: control client 'control-panel-status' presented a wrong run secret (trying again"
                    + " every 30 s)", line);
            assertEquals(1, log.size(), log.toString());
            assertTrue(log.get(0).contains("refuses this panel"), log.get(0));
            assertEquals(1, env.hellos.size(), "no second try at once with the same secret");
        }
    }

    @Test
    void afterTheRunStopsTheLineSaysStoppedAndThePanelBacksOffQuietly() throws Exception {
        BlockingQueue<RunStatus> statuses = new LinkedBlockingQueue<>();
        BlockingQueue<String> lines = new LinkedBlockingQueue<>();
        List<String> log = new CopyOnWriteArrayList<>();
        try (FakeEnvironment env = new FakeEnvironment();
             PanelSession s = PanelSession.withSecrets("127.0.0.1", env.port(), () -> null)) {
            s.poll(50, statuses::add, lines::add, log::add);
            assertEquals("fake", statuses.poll(10, TimeUnit.SECONDS).world());

            env.end("stopped by control client 'control-panel'");

            assertEquals("stopped: stopped by control client 'control-panel'", lines.poll(10, TimeUnit.SECONDS));
            // two more asks find nothing listening: the line stays, the log says nothing more
            assertEquals("stopped: stopped by control client 'control-panel'", lines.poll(10, TimeUnit.SECONDS));
            assertEquals("stopped: stopped by control client 'control-panel'", lines.poll(10, TimeUnit.SECONDS));
            assertEquals(1, log.size(), log.toString());
            assertTrue(log.get(0).contains("has stopped"), log.get(0));
        }
    }
}
