package robosim.protocol.recording;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import robosim.protocol.Figure;
import robosim.protocol.Snapshot;

/** A recording keeps the robots' drawings in the step they changed, with or without sensors. */
class RecordingDrawingsTest {
    @ParameterizedTest
    @ValueSource(booleans = {true, false})
    void theDrawingsComeBackInTheStepTheyChanged(boolean sensors) throws IOException {
        Snapshot.Drawing map = new Snapshot.Drawing("r1", "map",
                List.of(new Figure(Figure.CELLS, "", new double[] {0, 0, 1500, 1500})));
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (RecordingWriter w = new RecordingWriter(bytes, "drawings.rsr", sensors)) {
            w.world(Runs.world());
            w.snapshot(Runs.snapshot(0));
            w.snapshot(Runs.snapshot(1).withDrawings(List.of(map)));
            w.snapshot(Runs.snapshot(2));
            w.end("done");
        }
        try (RecordingReader reader = new RecordingReader(new ByteArrayInputStream(bytes.toByteArray()), "mem")) {
            assertEquals(List.of(), reader.next().drawings());
            assertEquals(List.of(map), reader.next().drawings());
            assertEquals(List.of(), reader.next().drawings());
        }
    }
}
