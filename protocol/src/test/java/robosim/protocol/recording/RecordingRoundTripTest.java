package robosim.protocol.recording;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;

/** A recording written and read back holds what was recorded, in few bytes, the same every time. */
class RecordingRoundTripTest {
    private static final MessageCodec CODEC = new MessageCodec();

    @TempDir
    Path dir;

    /** Encoding is deterministic, so equal bytes mean equal messages, arrays included. */
    private static void assertSameMessage(Message expected, Message actual) {
        assertArrayEquals(CODEC.encode(expected), CODEC.encode(actual), expected.toString());
    }

    private static List<Snapshot> readAll(RecordingReader reader) throws IOException {
        List<Snapshot> snapshots = new ArrayList<>();
        Snapshot f;
        while ((f = reader.next()) != null) {
            snapshots.add(f);
        }
        return snapshots;
    }

    @Test
    void everySnapshotComesBackWithItsSensorsMessagesAndSpeech() throws IOException {
        try (RecordingReader reader = new RecordingReader(new ByteArrayInputStream(Runs.record(true, true)), "mem")) {
            assertEquals(RecordingFormat.VERSION, reader.version());
            assertTrue(reader.sensors());
            assertSameMessage(Runs.world(), reader.world());
            List<Snapshot> snapshots = readAll(reader);
            assertEquals(Runs.STEPS + 1, snapshots.size());
            for (int i = 0; i < snapshots.size(); i++) {
                assertSameMessage(Runs.snapshot(i), snapshots.get(i));
            }
            assertEquals("done: step limit 10 reached", reader.endReason());
            assertNull(reader.next(), "nothing after the end");
        }
    }

    @Test
    void withoutSensorsTheRangesAreLeftOutAndEverythingElseKept() throws IOException {
        try (RecordingReader reader = new RecordingReader(new ByteArrayInputStream(Runs.record(false, true)), "mem")) {
            assertTrue(!reader.sensors());
            List<Snapshot> snapshots = readAll(reader);
            for (int i = 0; i < snapshots.size(); i++) {
                assertSameMessage(RecordingWriter.withoutSensors(Runs.snapshot(i)), snapshots.get(i));
                assertEquals(0, snapshots.get(i).robots().get(0).sonar().length);
                assertEquals(0, snapshots.get(i).robots().get(0).laser().length);
            }
            assertEquals("over here", snapshots.get(3).messages().get(0).body());
            assertEquals("hello", snapshots.get(2).said().get(0).text());
        }
    }

    @Test
    void theSameRunRecordedTwiceGivesIdenticalBytes() throws IOException {
        assertArrayEquals(Runs.record(true, true), Runs.record(true, true));
        assertArrayEquals(Runs.record(false, true), Runs.record(false, true));
    }

    @Test
    void aStepCostsFarLessThanItsWireFrame() throws IOException {
        byte[] recording = Runs.record(true, true);
        int wire = 0;
        for (Snapshot f : Runs.snapshots()) {
            wire += CODEC.encode(f).length;
        }
        int world = RecordingFormat.OVERHEAD + 400;
        assertTrue(recording.length - world < wire / 2,
                "recording of " + recording.length + " bytes vs " + wire + " bytes of wire frames");
    }

    @Test
    void aRecordingWithoutAnEndRecordReadsToItsLastStepWithNoReason() throws IOException {
        try (RecordingReader reader = new RecordingReader(new ByteArrayInputStream(Runs.record(true, false)), "mem")) {
            assertEquals(Runs.STEPS + 1, readAll(reader).size());
            assertNull(reader.endReason());
            assertEquals(Runs.STEPS, reader.lastStep());
        }
    }

    @Test
    void aFileIsCreatedWithItsDirectoriesAndReadWhole() throws IOException {
        Path file = dir.resolve("runs/one.rsr");
        try (RecordingWriter w = RecordingWriter.create(file, true)) {
            w.world(Runs.world());
            for (Snapshot f : Runs.snapshots()) {
                w.snapshot(f);
            }
            w.end("done");
            assertEquals(Files.size(file), w.bytesWritten(), "every record is flushed as it is written");
            assertEquals(Runs.STEPS + 1, w.snapshotsWritten());
        }
        Recording r = Recording.read(file);
        assertTrue(r.complete());
        assertEquals(Runs.STEPS + 1, r.snapshots().size());
        assertEquals("literal", r.world().name());
        assertEquals(Files.size(file), r.bytes());
        assertSameMessage(Runs.snapshot(7), r.snapshots().get(7).snapshot());
    }

    @Test
    void aSnapshotBeforeTheWorldIsRefused() throws IOException {
        try (RecordingWriter w = new RecordingWriter(new ByteArrayOutputStream(), "mem", true)) {
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> w.snapshot(Runs.snapshot(0)));
            assertTrue(e.getMessage().contains("before the world"), e.getMessage());
        }
    }
}
