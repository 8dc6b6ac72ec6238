package robosim.protocol.recording;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;

/**
 * Step 0 comes to a viewer when it attaches and again as the run starts: the recording keeps the
 * latest, so it is the same however the viewer's attach and the robots' connections raced.
 */
class RecordingStartTest {
    private static final MessageCodec CODEC = new MessageCodec();

    /** Step 0 as a viewer attached before the robots saw it: nobody connected yet. */
    private static Snapshot beforeTheRobots() {
        Snapshot start = Runs.snapshot(0);
        List<Snapshot.RobotView> waiting = start.robots().stream()
                .map(r -> new Snapshot.RobotView(r.name(), r.x(), r.y(), r.th(), false, false, r.sonar()))
                .toList();
        return new Snapshot(0, 0, waiting, List.of(), List.of());
    }

    private static List<byte[]> read(byte[] recording) throws IOException {
        try (RecordingReader r = new RecordingReader(new ByteArrayInputStream(recording), "mem")) {
            java.util.ArrayList<byte[]> out = new java.util.ArrayList<>();
            for (Snapshot s = r.next(); s != null; s = r.next()) {
                out.add(CODEC.encode(s));
            }
            return out;
        }
    }

    private static byte[] record(boolean attachFirst, boolean ended) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (RecordingWriter w = new RecordingWriter(bytes, "start.rsr", true)) {
            w.world(Runs.world());
            if (attachFirst) {
                w.snapshot(beforeTheRobots());
            }
            for (Snapshot s : Runs.snapshots()) {
                w.snapshot(s);
            }
            if (ended) {
                w.end("done");
            }
        }
        return bytes.toByteArray();
    }

    @Test
    void aViewerThatAttachedBeforeTheRobotsRecordsTheSameBytesAsOneThatCameAfter() throws IOException {
        assertArrayEquals(record(false, true), record(true, true));
        List<byte[]> snapshots = read(record(true, true));
        assertEquals(Runs.STEPS + 1, snapshots.size(), "one snapshot a step");
        assertArrayEquals(CODEC.encode(Runs.snapshot(0)), snapshots.get(0), "step 0 as the run started");
    }

    @Test
    void aRunThatEndsOrClosesAtStepZeroKeepsItsStart() throws IOException {
        for (boolean ended : new boolean[] {true, false}) {
            ByteArrayOutputStream bytes = new ByteArrayOutputStream();
            try (RecordingWriter w = new RecordingWriter(bytes, "start.rsr", true)) {
                w.world(Runs.world());
                w.snapshot(beforeTheRobots());
                if (ended) {
                    w.end("stopped before the start");
                }
            }
            List<byte[]> snapshots = read(bytes.toByteArray());
            assertEquals(1, snapshots.size(), ended ? "ended" : "closed");
            assertArrayEquals(CODEC.encode(beforeTheRobots()), snapshots.get(0));
        }
    }

    @Test
    void aWorldSentAgainDropsTheStepZeroBeforeIt() throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (RecordingWriter w = new RecordingWriter(bytes, "start.rsr", true)) {
            w.world(Runs.world());
            w.snapshot(beforeTheRobots());
            w.world(Runs.world()); // robots spawned before the start: the world again, then its step 0
            w.snapshot(Runs.snapshot(0));
            w.snapshot(Runs.snapshot(1));
        }
        try (RecordingReader r = new RecordingReader(new ByteArrayInputStream(bytes.toByteArray()), "mem")) {
            assertArrayEquals(CODEC.encode(Runs.snapshot(0)), CODEC.encode(r.next()));
            assertArrayEquals(CODEC.encode(Runs.snapshot(1)), CODEC.encode(r.next()));
            assertNull(r.next());
        }
    }
}
