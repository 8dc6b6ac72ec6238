package robosim.viewer.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.recording.RecordingReader;

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
}
