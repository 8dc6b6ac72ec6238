package robosim.protocol.recording;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.zip.DataFormatException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Fuzz;
import robosim.protocol.MessageCodec;
import robosim.protocol.RandomMessages;
import robosim.protocol.Snapshot;

/**
 * Seeded-random recordings of random worlds and snapshots, damaged three ways (see {@link Fuzz} to
 * replay a case or run more): bytes changed anywhere; a record's data changed and its checksum made
 * to match; a record's message changed before it is compressed, so that it reaches the codec. The
 * reader gives the snapshots of the records before the damage, exactly as they were written, then
 * ends cleanly or with a {@link RecordingException} naming the file and the offset of a record,
 * short and in printable ASCII whatever the damage; it never throws anything else.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class RecordingReaderFuzzTest {
    private static final String NAME = "fuzz.rsr";
    private static final MessageCodec CODEC = new MessageCodec();
    /** Damages made to each recording a case writes. */
    private static final int DAMAGES = 4;

    /** A recording as written: its bytes, where each record starts, and each snapshot's Smile bytes. */
    private record Written(byte[] bytes, List<Integer> offsets, List<byte[]> snapshots) {
        /** @return the number of snapshot records wholly before byte {@code at} */
        int snapshotsBefore(int at) {
            int n = 0;
            for (int k = 1; k < offsets.size(); k++) {
                int end = k + 1 < offsets.size() ? offsets.get(k + 1) : bytes.length;
                n += end <= at && k <= snapshots.size() ? 1 : 0;
            }
            return n;
        }

        /** @return the start of the record holding byte {@code at} */
        int recordOf(int at) {
            int start = offsets.get(0);
            for (int o : offsets) {
                start = o <= at ? o : start;
            }
            return start;
        }
    }

    /** What a reader made of a recording: the snapshots' Smile bytes, then the error (or null). */
    private record Read(List<byte[]> snapshots, RecordingException error) { }

    @Test
    void aFlippedBitEndsTheReadingAtItsRecord() {
        Fuzz.cases(0x5EED_0201L, 500, fuzz -> {
            Written w = write(fuzz);
            for (int n = 0; n < DAMAGES; n++) {
                int at = RecordingFormat.HEADER_LENGTH + fuzz.random().nextInt(w.bytes().length - RecordingFormat.HEADER_LENGTH);
                byte[] damaged = w.bytes().clone();
                damaged[at] ^= (byte) (1 << fuzz.random().nextInt(8));
                fuzz.input("bit flipped at byte " + at + " of " + damaged.length);

                Read read = read(damaged);

                assertTrue(read.error() != null, "a changed bit is always seen");
                assertEquals(w.recordOf(at), read.error().offset(), read.error().getMessage());
                sameAsWritten(w, read, w.snapshotsBefore(at));
            }
        });
    }

    @Test
    void damagedBytesAreReadOrRefusedWithARecordingException() {
        Fuzz.cases(0x5EED_0202L, 500, fuzz -> {
            Written w = write(fuzz);
            for (int n = 0; n < DAMAGES; n++) {
                byte[] damaged = fuzz.mutate(w.bytes());
                fuzz.input(damaged);

                Read read = read(damaged);

                if (read.error() != null) {
                    assertTrue(read.error().offset() >= 0 && read.error().offset() <= damaged.length, read.error().getMessage());
                }
            }
        });
    }

    @Test
    void aRecordWhoseChecksumMatchesItsDamageIsReadOrRefusedClearly() {
        Fuzz.cases(0x5EED_0203L, 500, fuzz -> {
            Written w = write(fuzz);
            for (int n = 0; n < DAMAGES; n++) {
                int k = fuzz.random().nextInt(w.offsets().size());
                int start = w.offsets().get(k);
                int end = k + 1 < w.offsets().size() ? w.offsets().get(k + 1) : w.bytes().length;
                byte kind = w.bytes()[start];
                byte[] data = Arrays.copyOfRange(w.bytes(), start + 5, end - 4);
                byte[] record = fuzz.random().nextBoolean() ? record(kind, fuzz.mutate(data))
                        : compressed(kind, fuzz.mutate(message(w, k)), k >= 2 && kind == RecordingFormat.SNAPSHOT
                                ? w.snapshots().get(k - 2) : null);
                byte[] damaged = Fuzz.splice(w.bytes(), start, end, record);
                fuzz.input("record " + k + " at byte " + start + " replaced: " + damaged.length + " bytes");

                Read read = read(damaged);

                if (read.error() != null) {
                    assertTrue(read.error().offset() >= start, read.error().getMessage());
                }
                int intact = w.snapshotsBefore(start);
                assertTrue(read.snapshots().size() >= intact, "the " + intact + " snapshots before the damage are read");
                sameAsWritten(w, new Read(read.snapshots().subList(0, intact), null), intact);
            }
        });
    }

    private static Written write(Fuzz fuzz) throws IOException {
        RandomMessages messages = new RandomMessages(fuzz.random());
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        List<Integer> offsets = new ArrayList<>();
        List<byte[]> snapshots = new ArrayList<>();
        try (RecordingWriter writer = new RecordingWriter(out, NAME, true)) {
            offsets.add(out.size());
            writer.world(messages.world());
            for (int n = fuzz.random().nextInt(6); n > 0; n--) {
                offsets.add(out.size());
                Snapshot s = messages.snapshot();
                while (s.step() == 0) {
                    s = messages.snapshot(); // a step 0 is held for the start: see RecordingStartTest
                }
                writer.snapshot(s);
                snapshots.add(CODEC.encode(s));
            }
            if (fuzz.random().nextBoolean()) {
                offsets.add(out.size());
                writer.end("done");
            }
        }
        return new Written(out.toByteArray(), offsets, snapshots);
    }

    /** @return the Smile bytes of record {@code k}: the world's for the first, else a snapshot's or the end's */
    private static byte[] message(Written w, int k) throws IOException {
        byte[] bytes = w.bytes();
        int start = w.offsets().get(k);
        int end = k + 1 < w.offsets().size() ? w.offsets().get(k + 1) : bytes.length;
        try (RecordCodec codec = new RecordCodec()) {
            byte[] dictionary = k >= 2 && bytes[start] == RecordingFormat.SNAPSHOT ? w.snapshots().get(k - 2) : null;
            return codec.decode(Arrays.copyOfRange(bytes, start + 5, end - 4), dictionary);
        } catch (DataFormatException e) {
            throw new IOException(e);
        }
    }

    /** @return a record holding {@code data} as it is, with a matching length and checksum */
    private static byte[] record(byte kind, byte[] data) {
        byte[] r = new byte[data.length + RecordingFormat.OVERHEAD];
        r[0] = kind;
        RecordCodec.putInt(r, 1, data.length);
        System.arraycopy(data, 0, r, 5, data.length);
        RecordCodec.putInt(r, 5 + data.length, RecordCodec.crc(kind, data.length, data));
        return r;
    }

    private static byte[] compressed(byte kind, byte[] message, byte[] dictionary) {
        try (RecordCodec codec = new RecordCodec()) {
            return codec.encode(kind, message, dictionary);
        }
    }

    private static Read read(byte[] bytes) throws IOException {
        List<byte[]> snapshots = new ArrayList<>();
        try (RecordingReader reader = new RecordingReader(new ByteArrayInputStream(bytes), NAME)) {
            Snapshot s;
            while ((s = reader.next()) != null) {
                snapshots.add(CODEC.encode(s));
            }
        } catch (RecordingException e) {
            assertTrue(e.getMessage().startsWith(NAME + ": ") || e.getMessage().startsWith(NAME + " is "),
                    e.getMessage());
            // what the file holds is quoted short and escaped: it cannot forge a line or reach a terminal
            assertTrue(e.getMessage().length() < 600, e.getMessage());
            assertTrue(e.getMessage().chars().allMatch(c -> c >= 0x20 && c < 0x7f), e.getMessage());
            return new Read(snapshots, e);
        }
        return new Read(snapshots, null);
    }

    private static void sameAsWritten(Written w, Read read, int count) {
        assertEquals(count, read.snapshots().size(), "snapshots read before the damage");
        for (int i = 0; i < count; i++) {
            assertArrayEquals(w.snapshots().get(i), read.snapshots().get(i), "snapshot " + i);
        }
    }
}
