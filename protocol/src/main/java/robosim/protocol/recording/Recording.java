package robosim.protocol.recording;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/**
 * A whole recording in memory, read as far as it can be: for replay windows and summaries, which
 * jump about in it. A damaged or cut-short file gives the snapshots before the damage and keeps the
 * {@link RecordingException} that stopped the reading.
 *
 * @param file      where it was read from
 * @param bytes     the file's size in bytes
 * @param sensors   whether the snapshots keep their sonar and laser readings
 * @param world     the world the recording starts in
 * @param snapshots    every snapshot read, in order, each with the world it is drawn in
 * @param endReason the end record's reason, or {@code null} if the run ended abruptly
 * @param problem   what stopped the reading early, or {@code null} if the whole file was read
 */
public record Recording(Path file, long bytes, boolean sensors, WorldDescription world, List<Step> snapshots, String endReason,
                        RecordingException problem) {
    /** Copies the list so the record stays immutable. */
    public Recording {
        snapshots = List.copyOf(snapshots);
    }

    /**
     * One step of the recording.
     *
     * @param world the world the snapshot is drawn in
     * @param snapshot the robots after the step
     */
    public record Step(WorldDescription world, Snapshot snapshot) { }

    /**
     * Reads a recording as far as it can be read.
     *
     * @param file the file
     * @return the recording
     * @throws RecordingException if not even its header and world can be read
     * @throws IOException        if the file cannot be read
     */
    public static Recording read(Path file) throws IOException {
        List<Step> steps = new ArrayList<>();
        RecordingException problem = null;
        try (RecordingReader reader = RecordingReader.open(file)) {
            WorldDescription first = reader.world();
            try {
                Snapshot f;
                while ((f = reader.next()) != null) {
                    steps.add(new Step(reader.world(), f));
                }
            } catch (RecordingException e) {
                problem = e;
            }
            return new Recording(file, Files.size(file), reader.sensors(), first, steps, reader.endReason(), problem);
        }
    }

    /** @return whether the whole file was read and it ends with an end record */
    public boolean complete() {
        return problem == null && endReason != null;
    }
}
