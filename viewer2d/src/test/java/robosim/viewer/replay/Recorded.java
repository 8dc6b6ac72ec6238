package robosim.viewer.replay;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.RecordingWriter;

/**
 * A literal recorded run: a 4000 x 2000 mm world with one block; r1 drives 100 mm a step along +x
 * from (500, 500) and stalls against something at steps 4 to 5 and again from step 8; r2 stands.
 */
final class Recorded {
    static final int LAST = 12;

    private Recorded() {
    }

    static WorldDescription world() {
        return new WorldDescription("recorded", 4000, 2000, 100,
                List.of(new WorldDescription.Obstacle(new double[] {1000, 1200, 1500, 1200, 1500, 1700, 1000, 1700}, 500)),
                List.of(new WorldDescription.RobotInfo("r1", "pioneer", null),
                        new WorldDescription.RobotInfo("r2", "pioneer", null)));
    }

    static Snapshot snapshot(int step) {
        boolean stalled = step == 4 || step == 5 || step >= 8;
        return new Snapshot(step, step * 100L, List.of(
                new RobotView("r1", 500 + 100 * step, 500, 0, stalled, true, new int[0]),
                new RobotView("r2", 3000, 1500, 90, false, true, new int[0])));
    }

    /** Writes steps 0 to {@link #LAST}, with the end record if {@code ended}. */
    static Path write(Path file, boolean ended) throws IOException {
        try (RecordingWriter w = RecordingWriter.create(file, false)) {
            w.world(world());
            for (int step = 0; step <= LAST; step++) {
                w.snapshot(snapshot(step));
            }
            if (ended) {
                w.end("done: step limit 12 reached");
            }
        }
        return file;
    }
}
