package robosim.protocol.recording;

import java.io.BufferedInputStream;
import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.zip.DataFormatException;
import robosim.protocol.Bye;
import robosim.protocol.FrameException;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/**
 * Reads a recording (see {@link RecordingFormat}) step by step. Opening it reads the header and
 * the world; {@link #next()} then gives one snapshot per call. A record that is cut short or fails
 * its check ends the reading with a {@link RecordingException} naming the file, the byte offset
 * and the last step read whole; every snapshot before it has already been given out.
 */
public final class RecordingReader implements Closeable {
    private final InputStream in;
    private final String name;
    /** One codec for all: Jackson builds its (de)serializers once per codec, which costs more than a short recording. */
    private static final MessageCodec CODEC = new MessageCodec();
    private final RecordCodec records = new RecordCodec();
    private final int version;
    private final boolean sensors;
    private WorldDescription world;
    private byte[] previousSnapshot;
    private long offset;
    private long lastStep = -1;
    private String endReason;
    private boolean finished;

    /**
     * Reads the header and the world record.
     *
     * @param in   the recording's bytes; the reader owns the stream from then on
     * @param name what to call the recording in messages, such as its file name
     * @throws RecordingException if it is not a recording, is of a newer version, or its world
     *                            record is missing or damaged
     * @throws IOException        if the stream fails
     */
    public RecordingReader(InputStream in, String name) throws IOException {
        this.in = new BufferedInputStream(in, 1 << 16);
        this.name = name;
        byte[] header = new byte[RecordingFormat.HEADER_LENGTH];
        int got = readUpTo(header);
        byte[] magic = Arrays.copyOf(header, Math.min(got, RecordingFormat.MAGIC.length));
        if (!Arrays.equals(magic, RecordingFormat.MAGIC)) {
            throw new RecordingException(name + " is not a RoboSim recording: it starts with "
                    + quote(magic) + ", not the magic \"RoboSimR\"", 0, -1, false, null);
        }
        if (got < header.length) {
            throw truncated(0, got, header.length, "header");
        }
        offset = header.length;
        version = ((header[8] & 0xff) << 8) | (header[9] & 0xff);
        if (version < 1 || version > RecordingFormat.VERSION) {
            throw new RecordingException(name + " is a recording of format version " + version
                    + ": this RoboSim reads versions 1 to " + RecordingFormat.VERSION, 8, -1, false, null);
        }
        sensors = (header[11] & RecordingFormat.FLAG_SENSORS) != 0;
        long at = offset;
        Message first = readRecord();
        if (!(first instanceof WorldDescription w)) {
            throw corrupt(at, first == null ? "the recording holds no world record"
                    : "a recording starts with its world ('W' record), not a " + first.getClass().getSimpleName(), null);
        }
        world = w;
    }

    /**
     * Opens a recording file.
     *
     * @param file the file
     * @return a reader, positioned after the world
     * @throws IOException if the file cannot be read or does not start as a recording should
     */
    public static RecordingReader open(Path file) throws IOException {
        InputStream in = Files.newInputStream(file);
        try {
            return new RecordingReader(in, file.toString());
        } catch (IOException | RuntimeException e) {
            in.close();
            throw e;
        }
    }

    /**
     * Reads the next step's snapshot; a world record on the way replaces {@link #world()}.
     *
     * @return the snapshot, or {@code null} after the end record or at the end of the file
     * @throws RecordingException if the next record is cut short or damaged
     * @throws IOException        if the stream fails
     */
    public Snapshot next() throws IOException {
        while (!finished) {
            Message m = readRecord();
            if (m == null) {
                finished = true;
            } else if (m instanceof Snapshot snapshot) {
                lastStep = snapshot.step();
                return snapshot;
            } else if (m instanceof WorldDescription w) {
                world = w;
            } else if (m instanceof Bye bye) {
                endReason = bye.reason();
                finished = true;
            }
        }
        return null;
    }

    /** @return null at a clean end of file; otherwise the record's message, of the kind's type */
    private Message readRecord() throws IOException {
        long at = offset;
        int kind = in.read();
        if (kind < 0) {
            return null;
        }
        byte[] head = new byte[4];
        int got = readUpTo(head);
        if (got < 4) {
            throw truncated(at, 1 + got, RecordingFormat.OVERHEAD, "record");
        }
        int length = ((head[0] & 0xff) << 24) | ((head[1] & 0xff) << 16) | ((head[2] & 0xff) << 8) | (head[3] & 0xff);
        if (kind != RecordingFormat.WORLD && kind != RecordingFormat.SNAPSHOT && kind != RecordingFormat.END) {
            throw corrupt(at, "record kind " + RecordingFormat.describe(kind) + " is not one of 'W', 'F', 'E'", null);
        }
        if (length < 1 || length > RecordingFormat.MAX_RECORD) {
            throw corrupt(at, "a " + RecordingFormat.describe(kind) + " record claims " + Integer.toUnsignedString(length)
                    + " bytes of data: a record holds 1 to " + RecordingFormat.MAX_RECORD, null);
        }
        byte[] data = new byte[length];
        got = readUpTo(data);
        if (got < length) {
            throw truncated(at, 5 + got, length + RecordingFormat.OVERHEAD, "record");
        }
        got = readUpTo(head);
        if (got < 4) {
            throw truncated(at, 5 + length + got, length + RecordingFormat.OVERHEAD, "record");
        }
        int stored = ((head[0] & 0xff) << 24) | ((head[1] & 0xff) << 16) | ((head[2] & 0xff) << 8) | (head[3] & 0xff);
        int computed = RecordCodec.crc(kind, length, data);
        if (stored != computed) {
            throw corrupt(at, String.format("the %s record's CRC-32 is %08x but its bytes give %08x: every record"
                    + " must match its checksum", RecordingFormat.describe(kind), stored, computed), null);
        }
        Message m = decode(at, kind, data);
        offset = at + RecordingFormat.OVERHEAD + length;
        return m;
    }

    private Message decode(long at, int kind, byte[] data) throws RecordingException {
        byte[] dictionary = kind == RecordingFormat.SNAPSHOT ? previousSnapshot : null;
        byte[] smile;
        Message m;
        try {
            smile = records.decode(data, dictionary);
            m = CODEC.decode(smile);
        } catch (DataFormatException | FrameException e) {
            throw corrupt(at, "the " + RecordingFormat.describe(kind) + " record cannot be decoded: " + e.getMessage(), e);
        }
        Class<?> expected = kind == RecordingFormat.WORLD ? WorldDescription.class
                : kind == RecordingFormat.SNAPSHOT ? Snapshot.class : Bye.class;
        if (!expected.isInstance(m)) {
            throw corrupt(at, "the " + RecordingFormat.describe(kind) + " record holds a "
                    + m.getClass().getSimpleName() + ", not a " + expected.getSimpleName(), null);
        }
        if (kind == RecordingFormat.SNAPSHOT) {
            previousSnapshot = smile;
        }
        return m;
    }

    private int readUpTo(byte[] b) throws IOException {
        int n = 0;
        while (n < b.length) {
            int r = in.read(b, n, b.length - n);
            if (r < 0) {
                break;
            }
            n += r;
        }
        return n;
    }

    private RecordingException truncated(long at, long present, long whole, String what) {
        return new RecordingException(name + ": the recording ends inside the " + what + " at byte offset " + at
                + " (" + present + " of at least " + whole + " bytes present), after step " + lastStep
                + readable(), at, lastStep, true, null);
    }

    private RecordingException corrupt(long at, String problem, Throwable cause) {
        return new RecordingException(name + ": bad record at byte offset " + at + ", after step " + lastStep + ": "
                + problem + readable(), at, lastStep, false, cause);
    }

    private String readable() {
        return lastStep < 0 ? "; no step is readable" : "; steps up to " + lastStep + " are readable";
    }

    private static String quote(byte[] bytes) {
        String s = new String(bytes, StandardCharsets.ISO_8859_1);
        return bytes.length == 0 ? "nothing" : "\"" + s.replaceAll("[^\\x20-\\x7e]", "?") + "\"";
    }

    /** @return the world the latest snapshot is drawn in */
    public WorldDescription world() {
        return world;
    }

    /** @return the recording's format version */
    public int version() {
        return version;
    }

    /** @return whether the snapshots keep their sonar and laser readings */
    public boolean sensors() {
        return sensors;
    }

    /** @return the end record's reason once it has been read; {@code null} before, or if the run ended abruptly */
    public String endReason() {
        return endReason;
    }

    /** @return the bytes read whole so far, header included */
    public long offset() {
        return offset;
    }

    /** @return the step of the last snapshot read, or -1 */
    public long lastStep() {
        return lastStep;
    }

    /** @return the name the reader calls the recording in messages */
    public String name() {
        return name;
    }

    @Override
    public void close() throws IOException {
        records.close();
        in.close();
    }
}
