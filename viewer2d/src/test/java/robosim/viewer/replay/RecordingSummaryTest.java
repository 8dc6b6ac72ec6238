package robosim.viewer.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.Snapshot;
import robosim.protocol.recording.RecordingReader;
import robosim.protocol.recording.RecordingWriter;

/** The summary of a recording: distance from the true poses, collisions as stalls begun. */
class RecordingSummaryTest {
    @TempDir
    Path dir;

    @Test
    void distanceAndCollisionsComeFromTheTruePoses() throws IOException {
        RecordingSummary s;
        try (RecordingReader reader = RecordingReader.open(Recorded.write(dir.resolve("run.rsr"), true))) {
            s = RecordingSummary.of(reader);
        }
        assertEquals("recorded", s.world());
        assertEquals(13, s.snapshots());
        assertEquals(0, s.firstStep());
        assertEquals(12, s.lastStep());
        assertEquals(1200, s.timeMs());
        assertEquals("done: step limit 12 reached", s.endReason());
        assertNull(s.problem());
        RecordingSummary.RobotTotals r1 = s.robots().get(0);
        assertEquals("r1", r1.name());
        assertEquals(1200, r1.distance(), 1e-9, "12 steps of 100 mm");
        assertEquals(2, r1.collisions(), "stalled at step 4 and again at step 8");
        assertEquals(1700, r1.x());
        RecordingSummary.RobotTotals r2 = s.robots().get(1);
        assertEquals(0, r2.distance());
        assertEquals(0, r2.collisions());
    }

    @Test
    void theMetricsLastReportedAndTheEndRequestAreSummedUp() throws IOException {
        Path file = dir.resolve("metrics.rsr");
        Snapshot.EndRequest end = new Snapshot.EndRequest("r2", 3, "gold found");
        try (RecordingWriter w = RecordingWriter.create(file, false)) {
            w.world(Recorded.world());
            w.snapshot(Recorded.snapshot(0));
            w.snapshot(Recorded.snapshot(1).withRunEvents(List.of(new Snapshot.Metric("r2", "cells", 1),
                    new Snapshot.Metric("r1", "cells", 2)), null));
            w.snapshot(Recorded.snapshot(2).withRunEvents(List.of(new Snapshot.Metric("r1", "turns", 5),
                    new Snapshot.Metric("r1", "cells", 3)), null));
            w.snapshot(Recorded.snapshot(3).withRunEvents(List.of(), end));
            w.end("done: ended by robot r2 at step 3: gold found");
        }
        RecordingSummary s;
        try (RecordingReader reader = RecordingReader.open(file)) {
            s = RecordingSummary.of(reader);
        }
        Map<String, Double> r1 = new LinkedHashMap<>();
        r1.put("cells", 3.0);
        r1.put("turns", 5.0);
        assertEquals(List.of("r2", "r1"), List.copyOf(s.metrics().keySet()), "in the order first reported");
        assertEquals(r1, s.metrics().get("r1"));
        assertEquals(List.of("cells", "turns"), List.copyOf(s.metrics().get("r1").keySet()));
        assertEquals(Map.of("cells", 1.0), s.metrics().get("r2"));
        assertEquals(end, s.endRequest());
    }

    @Test
    void aRecordingWithoutThemHasNone() throws IOException {
        RecordingSummary s;
        try (RecordingReader reader = RecordingReader.open(Recorded.write(dir.resolve("run.rsr"), true))) {
            s = RecordingSummary.of(reader);
        }
        assertEquals(Map.of(), s.metrics());
        assertNull(s.endRequest());
    }
}
