package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.SnapshotListener;

@Timeout(value = 30, unit = TimeUnit.SECONDS)
class QueuedListenerTest {
    private static final WorldDescription WORLD = new WorldDescription("w", 1000, 1000, 100, List.of(), List.of());

    /** Notes each call and the thread it came on. */
    private static final class Notes implements SnapshotListener {
        final List<String> calls = new CopyOnWriteArrayList<>();
        final List<String> threads = new CopyOnWriteArrayList<>();
        final long failAt;

        Notes(long failAt) {
            this.failAt = failAt;
        }

        @Override
        public void world(WorldDescription world) {
            note("world " + world.name());
        }

        @Override
        public void snapshot(Snapshot snapshot) throws IOException {
            if (snapshot.step() == failAt) {
                throw new IOException("disk full at step " + failAt);
            }
            note("step " + snapshot.step());
        }

        @Override
        public void end(String reason) {
            note("end " + reason);
        }

        @Override
        public void close() {
            note("close");
        }

        private void note(String call) {
            calls.add(call);
            threads.add(Thread.currentThread().getName());
        }
    }

    @Test
    void callsArriveInOrderOnTheListenersOwnThreadAndCloseWaitsForThem() throws Exception {
        Notes notes = new Notes(-1);
        QueuedListener queued = new QueuedListener("drawing", notes);
        queued.world(WORLD);
        for (int step = 0; step < 3; step++) {
            queued.snapshot(new Snapshot(step, step * 100L, List.of()));
        }
        queued.end("done");
        queued.close();
        assertEquals(List.of("world w", "step 0", "step 1", "step 2", "end done", "close"), notes.calls);
        assertEquals(List.of("drawing"), notes.threads.stream().distinct().toList());
        assertNotEquals("drawing", Thread.currentThread().getName());
    }

    @Test
    void aFailureStopsTheCallsButTheTargetIsStillClosedAndCloseThrowsIt() throws Exception {
        Notes notes = new Notes(1);
        QueuedListener queued = new QueuedListener("drawing", notes);
        queued.world(WORLD);
        queued.snapshot(new Snapshot(0, 0, List.of()));
        queued.snapshot(new Snapshot(1, 100, List.of()));
        try {
            queued.snapshot(new Snapshot(2, 200, List.of()));
        } catch (IOException early) {
            // the drawing thread may have failed already: then the next call says so at once
            assertEquals("disk full at step 1", early.getMessage());
        }
        IOException e = assertThrows(IOException.class, queued::close);
        assertEquals("disk full at step 1", e.getMessage());
        assertEquals(List.of("world w", "step 0", "close"), notes.calls);
    }
}
