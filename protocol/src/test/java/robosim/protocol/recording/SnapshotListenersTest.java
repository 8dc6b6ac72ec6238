package robosim.protocol.recording;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/** One failing listener is dropped and closed; the others follow the run to its end. */
class SnapshotListenersTest {
    /** Notes every call; fails on the snapshot of one step if asked to. */
    private static final class Noting implements SnapshotListener {
        final List<String> calls = new ArrayList<>();
        final long failAt;

        Noting(long failAt) {
            this.failAt = failAt;
        }

        @Override
        public void world(WorldDescription world) {
            calls.add("world " + world.name());
        }

        @Override
        public void snapshot(Snapshot snapshot) throws IOException {
            if (snapshot.step() == failAt) {
                throw new IOException("disk full");
            }
            calls.add("snapshot " + snapshot.step());
        }

        @Override
        public void end(String reason) {
            calls.add("end " + reason);
        }

        @Override
        public void close() {
            calls.add("close");
        }
    }

    @Test
    void aFailingListenerIsDroppedAndTheOthersGoOn() {
        Noting failing = new Noting(2);
        Noting fine = new Noting(-1);
        SnapshotListeners all = new SnapshotListeners();
        all.add(failing);
        all.add(fine);
        all.world(Runs.world());
        for (int step = 0; step <= 3; step++) {
            all.snapshot(Runs.snapshot(step));
        }
        all.end("done");
        all.close();
        assertEquals(List.of("world literal", "snapshot 0", "snapshot 1", "close"), failing.calls);
        assertEquals(List.of("world literal", "snapshot 0", "snapshot 1", "snapshot 2", "snapshot 3", "end done", "close"), fine.calls);
        assertEquals(0, all.size(), "closing forgets them");
    }
}
