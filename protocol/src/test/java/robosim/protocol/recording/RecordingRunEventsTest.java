package robosim.protocol.recording;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import robosim.protocol.Snapshot;

/** A recording keeps the metrics robots reported and the request that ended the run, in their steps. */
class RecordingRunEventsTest {
    @ParameterizedTest
    @ValueSource(booleans = {true, false})
    void theMetricsAndTheEndRequestComeBackInTheStepTheyCameIn(boolean sensors) throws IOException {
        List<Snapshot.Metric> step1 = List.of(new Snapshot.Metric("r1", "cells", 3),
                new Snapshot.Metric("r2", "cells", 1));
        List<Snapshot.Metric> step2 = List.of(new Snapshot.Metric("r1", "cells", 4));
        Snapshot.EndRequest end = new Snapshot.EndRequest("r2", 2, "gold found");
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (RecordingWriter w = new RecordingWriter(bytes, "metrics.rsr", sensors)) {
            w.world(Runs.world());
            w.snapshot(Runs.snapshot(0));
            w.snapshot(Runs.snapshot(1).withRunEvents(step1, null));
            w.snapshot(Runs.snapshot(2).withRunEvents(step2, end));
            w.end("done: ended by robot r2 at step 2: gold found");
        }
        try (RecordingReader reader = new RecordingReader(new ByteArrayInputStream(bytes.toByteArray()), "mem")) {
            Snapshot s0 = reader.next();
            assertEquals(List.of(), s0.metrics());
            assertNull(s0.endRequest());
            Snapshot s1 = reader.next();
            assertEquals(step1, s1.metrics());
            assertNull(s1.endRequest());
            Snapshot s2 = reader.next();
            assertEquals(step2, s2.metrics());
            assertEquals(end, s2.endRequest());
            assertNull(reader.next());
            assertEquals("done: ended by robot r2 at step 2: gold found", reader.endReason());
        }
    }
}
