package robosim.protocol.recording;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/** A recording keeps the world's pucks and where each is at every step, with or without sensors. */
class RecordingObjectsTest {
    @ParameterizedTest
    @ValueSource(booleans = {true, false})
    void thePucksComeBackAtEveryStep(boolean sensors) throws IOException {
        WorldDescription world = Runs.world().withObjects(
                List.of(new WorldDescription.WorldObject("puck", 2000, 1000, 38, "red")));
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (RecordingWriter w = new RecordingWriter(bytes, "pucks.rsr", sensors)) {
            w.world(world);
            for (int step = 0; step <= 3; step++) {
                w.snapshot(Runs.snapshot(step).withObjects(
                        List.of(new Snapshot.ObjectView(2000 + 10 * step, 1000, step >= 2 ? "r1" : null, step == 3))));
            }
            w.end("done");
        }
        try (RecordingReader reader = new RecordingReader(new ByteArrayInputStream(bytes.toByteArray()), "mem")) {
            assertEquals(world.objects(), reader.world().objects());
            for (int step = 0; step <= 3; step++) {
                Snapshot f = reader.next();
                assertEquals(List.of(new Snapshot.ObjectView(2000 + 10 * step, 1000, step >= 2 ? "r1" : null,
                        step == 3)), f.objects(), "step " + step);
            }
        }
    }
}
