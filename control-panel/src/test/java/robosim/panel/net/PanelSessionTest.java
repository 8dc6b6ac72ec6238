package robosim.panel.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
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
            s.poll(50, statuses::add, why -> { });

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
            s.poll(50, statuses::add, why -> { });

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
}
