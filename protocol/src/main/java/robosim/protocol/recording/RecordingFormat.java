package robosim.protocol.recording;

import java.nio.charset.StandardCharsets;

/**
 * The recording file format, version {@value #VERSION}; docs/VIEWER.md describes it for readers in
 * other languages.
 *
 * <pre>
 * header   8 bytes  magic "RoboSimR" (ASCII)
 *          2 bytes  format version, big-endian ({@value #VERSION})
 *          2 bytes  flags, big-endian: bit 0 set when sonar and laser readings are kept
 * records, each:
 *          1 byte   kind: 'W' the world, 'F' the snapshot after one step, 'E' the end of the run
 *          4 bytes  length L of the data, big-endian, 1 to {@value #MAX_RECORD}
 *          L bytes  data: one protocol message (WorldDescription, Snapshot, Bye) encoded as
 *                   Smile, then compressed as raw DEFLATE; an 'F' record's DEFLATE dictionary is
 *                   the Smile bytes of the previous 'F' record (none for the first), so that a
 *                   step costs little more than what changed in it
 *          4 bytes  CRC-32 of the kind byte, the length bytes and the data, big-endian
 * </pre>
 *
 * <p>A recording holds a 'W' record first, then an 'F' record per step, and an 'E' record when
 * the run ended in order. Nothing in it depends on the wall clock or on hash order, so a
 * deterministic run recorded twice gives identical bytes. Each record is written with one write,
 * so a run that ends abruptly leaves every step but perhaps the last readable.
 */
public final class RecordingFormat {
    /** The first eight bytes of every recording. */
    static final byte[] MAGIC = "RoboSimR".getBytes(StandardCharsets.US_ASCII);
    /** The format version this code writes and the newest it reads. */
    public static final int VERSION = 1;
    /** Bytes before the first record. */
    public static final int HEADER_LENGTH = 12;
    /** Header flag: the snapshots keep their sonar and laser readings. */
    static final int FLAG_SENSORS = 1;
    /** Record kind: the world. */
    static final byte WORLD = 'W';
    /** Record kind: one step's snapshot. */
    static final byte SNAPSHOT = 'F';
    /** Record kind: the run's end. */
    static final byte END = 'E';
    /** Bytes of a record besides its data: kind, length, CRC. */
    static final int OVERHEAD = 9;
    /** The largest data a record may hold, 16 MiB; checked before anything is allocated. */
    public static final int MAX_RECORD = 16 << 20;
    /** The largest message a record may inflate to, 64 MiB. */
    static final int MAX_MESSAGE = 64 << 20;

    private RecordingFormat() {
    }

    /**
     * @param kind a record's kind byte
     * @return its description for messages, such as {@code 'F' (frame)}
     */
    static String describe(int kind) {
        String what = switch (kind) {
            case WORLD -> "world";
            case SNAPSHOT -> "frame";
            case END -> "end";
            default -> "unknown";
        };
        return kind >= 0x20 && kind < 0x7f ? "'" + (char) kind + "' (" + what + ")"
                : String.format("0x%02x (%s)", kind, what);
    }
}
