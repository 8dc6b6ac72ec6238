package robosim.viewer.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.Bye;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;
import robosim.protocol.recording.Recording;
import robosim.protocol.recording.RecordingWriter;
import robosim.viewer.draw.Fixtures;

/** A viewer that passes the run to listeners: a recorder, and a stop from another thread. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ViewerClientListenersTest {
    @TempDir
    Path tmp;

    private static ViewerOptions options(int port) {
        return ViewerOptions.of("127.0.0.1", port).withName("listening")
                .withConnectTimeout(Duration.ofSeconds(5)).withReadTimeout(Duration.ofSeconds(5));
    }

    @Test
    void aRecorderGetsTheWorldEverySnapshotAndTheEnd() throws Exception {
        Path file = tmp.resolve("viewer.rsr");
        try (FakeEnvironment env = new FakeEnvironment((out, socket) -> {
            out.write(Fixtures.world());
            for (int step = 0; step <= 5; step++) {
                out.write(Fixtures.snapshot(step, Fixtures.robot(1000 + 100 * step, 1500, 0, false, true)));
            }
            out.write(new Bye("done: step limit 5 reached"));
        })) {
            ViewerSummary s = new ViewerClient(options(env.port()), List.of(RecordingWriter.create(file, true))).run();
            assertEquals(new ViewerSummary("fixture", 6, 5, "done: step limit 5 reached"), s);
        }
        Recording r = Recording.read(file);
        assertTrue(r.complete());
        assertEquals("done: step limit 5 reached", r.endReason());
        assertEquals(6, r.snapshots().size());
        assertEquals(1500, r.snapshots().get(5).snapshot().robots().get(0).x());
    }

    @Test
    void stopFromAnotherThreadEndsTheRunAndClosesTheListeners() throws Exception {
        CountDownLatch framed = new CountDownLatch(1);
        CountDownLatch closed = new CountDownLatch(1);
        SnapshotListener listener = new SnapshotListener() {
            @Override
            public void world(WorldDescription world) {
            }

            @Override
            public void snapshot(Snapshot snapshot) {
                framed.countDown();
            }

            @Override
            public void close() {
                closed.countDown();
            }
        };
        try (FakeEnvironment env = new FakeEnvironment((out, socket) -> {
            out.write(Fixtures.world());
            out.write(Fixtures.snapshot(1, Fixtures.robotAtRest()));
        })) {
            ViewerClient client = new ViewerClient(options(env.port()), List.of(listener));
            // a thread of its own: the common pool may have a single worker on two cores
            CompletableFuture<ViewerSummary> run = CompletableFuture.supplyAsync(() -> {
                try {
                    return client.run();
                } catch (ViewerException e) {
                    throw new IllegalStateException(e);
                }
            }, task -> new Thread(task, "viewer").start());
            assertTrue(framed.await(10, TimeUnit.SECONDS));
            client.stop();
            assertEquals("stopped", run.get(10, TimeUnit.SECONDS).endReason());
            assertTrue(closed.await(10, TimeUnit.SECONDS));
        }
    }
}
