package robosim.protocol.recording;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import robosim.protocol.Bye;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;

/**
 * Writes a recording (see {@link RecordingFormat}): attach it to an Environment or a viewer as a
 * {@link SnapshotListener}. Every record goes out in one write and is flushed, so the file is
 * readable up to the last step even if the process dies. A snapshot of step 0 is held until a later
 * step, the end or the close, and a later snapshot of step 0 takes its place: a viewer attached
 * while the robots connect is sent step 0 then and again as the run starts, and the recording keeps
 * the start, the same however the connections raced. Not thread-safe: one feeder at a time.
 */
public final class RecordingWriter implements SnapshotListener {
    private static final int[] NONE = new int[0];

    private final OutputStream out;
    private final String name;
    private final boolean sensors;
    /** One codec for all: Jackson builds its (de)serializers once per codec, which costs more than a short recording. */
    private static final MessageCodec CODEC = new MessageCodec();
    private final RecordCodec records = new RecordCodec();
    private byte[] previousSnapshot;
    /** The latest snapshot of step 0, not yet written; null when there is none. */
    private Snapshot start;
    private long bytes;
    private long snapshots;
    private boolean worldWritten;
    private boolean closed;
    private IOException failure;

    /**
     * Writes the header to a stream; the writer owns the stream from then on.
     *
     * @param out     where the recording goes
     * @param name    what to call it in messages, such as its file name
     * @param sensors whether to keep each robot's sonar and laser readings; without them a step
     *                costs about half as much and the replay draws no sensor rays
     * @throws IOException if the header cannot be written
     */
    public RecordingWriter(OutputStream out, String name, boolean sensors) throws IOException {
        if (out == null) {
            throw new IllegalArgumentException("null was supplied for out: a stream is required");
        }
        this.out = out;
        this.name = name;
        this.sensors = sensors;
        byte[] header = new byte[RecordingFormat.HEADER_LENGTH];
        System.arraycopy(RecordingFormat.MAGIC, 0, header, 0, RecordingFormat.MAGIC.length);
        header[8] = (byte) (RecordingFormat.VERSION >>> 8);
        header[9] = (byte) RecordingFormat.VERSION;
        header[11] = (byte) (sensors ? RecordingFormat.FLAG_SENSORS : 0);
        put(header);
    }

    /**
     * Creates (or replaces) a recording file, with its parent directories.
     *
     * @param file    the file
     * @param sensors whether to keep sonar and laser readings
     * @return the writer, its header written
     * @throws IOException if the file cannot be created
     */
    public static RecordingWriter create(Path file, boolean sensors) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        return new RecordingWriter(Files.newOutputStream(file), file.toString(), sensors);
    }

    @Override
    public void world(WorldDescription world) throws IOException {
        start = null; // a world sent again is followed by its step 0
        put(records.encode(RecordingFormat.WORLD, CODEC.encode(world), null));
        worldWritten = true;
    }

    @Override
    public void snapshot(Snapshot snapshot) throws IOException {
        if (!worldWritten) {
            throw new IllegalStateException("snapshot of step " + snapshot.step() + " for " + name
                    + " before the world: a recording starts with its world");
        }
        if (snapshot.step() == 0) {
            start = snapshot;
            return;
        }
        writeStart();
        write(snapshot);
    }

    /** Writes the held snapshot of step 0, if there is one. */
    private void writeStart() throws IOException {
        if (start != null) {
            Snapshot s = start;
            start = null;
            write(s);
        }
    }

    private void write(Snapshot snapshot) throws IOException {
        byte[] message = CODEC.encode(sensors ? snapshot : withoutSensors(snapshot));
        put(records.encode(RecordingFormat.SNAPSHOT, message, previousSnapshot));
        previousSnapshot = message;
        snapshots++;
    }

    @Override
    public void end(String reason) throws IOException {
        writeStart();
        put(records.encode(RecordingFormat.END, CODEC.encode(new Bye(reason)), null));
    }

    private void put(byte[] record) throws IOException {
        if (closed) {
            throw new IOException("recording " + name + " is closed");
        }
        try {
            out.write(record);
            out.flush();
        } catch (IOException e) {
            failure = e;
            throw new IOException("cannot write recording " + name + ": " + e.getMessage(), e);
        }
        bytes += record.length;
    }

    /** @return the write that failed, or {@code null} if none has */
    public IOException failure() {
        return failure;
    }

    /** @return {@code recording NAME}, for log lines about it */
    @Override
    public String toString() {
        return "recording " + name;
    }

    /** @return the bytes written so far, header included */
    public long bytesWritten() {
        return bytes;
    }

    /** @return the snapshots written so far */
    public long snapshotsWritten() {
        return snapshots;
    }

    /** @return whether sonar and laser readings are kept */
    public boolean sensors() {
        return sensors;
    }

    /** Closes the file; a recording without an end record reads as one that ended abruptly. */
    @Override
    public void close() throws IOException {
        if (!closed) {
            try {
                if (failure == null) {
                    writeStart();
                }
            } finally {
                closed = true;
                records.close();
                out.close();
            }
        }
    }

    /**
     * @param snapshot a snapshot
     * @return the snapshot with every robot's sonar and laser readings left out (its camera's two
     *         numbers, pan and field of view, stay)
     */
    static Snapshot withoutSensors(Snapshot snapshot) {
        List<RobotView> robots = new ArrayList<>(snapshot.robots().size());
        for (RobotView r : snapshot.robots()) {
            robots.add(new RobotView(r.name(), r.x(), r.y(), r.th(), r.stalled(), r.connected(), NONE,
                    r.odoX(), r.odoY(), r.odoTh(), NONE, r.laserIncrement(), r.vel(), r.rotVel(), r.camera()));
        }
        return new Snapshot(snapshot.step(), snapshot.timeMs(), robots, snapshot.messages(), snapshot.said(),
                snapshot.events(), snapshot.objects(), snapshot.drawings(), snapshot.metrics(), snapshot.endRequest());
    }
}
