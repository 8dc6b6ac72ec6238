package robosim.protocol.recording;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.Snapshot;

/**
 * Cut-short and damaged recordings: the snapshots before the damage are read, then an error names the
 * file, the byte offset of the bad record and the last good step.
 */
class DamagedRecordingTest {
    @TempDir
    Path dir;

    /** Where each record starts: [0] the world, [1 + k] the snapshot of step k, last the end record. */
    private static List<Integer> recordOffsets(byte[] recording) {
        List<Integer> offsets = new ArrayList<>();
        int at = RecordingFormat.HEADER_LENGTH;
        while (at < recording.length) {
            offsets.add(at);
            int length = ((recording[at + 1] & 0xff) << 24) | ((recording[at + 2] & 0xff) << 16)
                    | ((recording[at + 3] & 0xff) << 8) | (recording[at + 4] & 0xff);
            at += RecordingFormat.OVERHEAD + length;
        }
        return offsets;
    }

    /** Reads every snapshot it can; returns them, and the exception that stopped it (or null). */
    private static Object[] readAsFarAsPossible(byte[] bytes) throws IOException {
        List<Snapshot> snapshots = new ArrayList<>();
        try (RecordingReader r = new RecordingReader(new ByteArrayInputStream(bytes), "run.rsr")) {
            Snapshot f;
            while ((f = r.next()) != null) {
                snapshots.add(f);
            }
        } catch (RecordingException e) {
            return new Object[] {snapshots, e};
        }
        return new Object[] {snapshots, null};
    }

    @Test
    void cutAtEveryByteReadsEveryWholeStepThenSaysWhereItEnds() throws IOException {
        byte[] whole = Runs.record(false, true);
        List<Integer> offsets = recordOffsets(whole);
        for (int cut = offsets.get(1); cut < whole.length; cut++) {
            Object[] read = readAsFarAsPossible(Arrays.copyOf(whole, cut));
            @SuppressWarnings("unchecked")
            List<Snapshot> snapshots = (List<Snapshot>) read[0];
            int wholeFrames = 0;
            for (int k = 1; k < offsets.size() - 1; k++) {
                int end = k + 1 < offsets.size() ? offsets.get(k + 1) : whole.length;
                if (end <= cut) {
                    wholeFrames++;
                }
            }
            assertEquals(wholeFrames, snapshots.size(), "cut at byte " + cut);
            RecordingException e = (RecordingException) read[1];
            if (offsets.contains(cut)) {
                assertEquals(null, e, "a cut between records is a clean (abrupt) end");
                continue;
            }
            assertTrue(e != null && e.truncated(), "cut at byte " + cut);
            int start = 0;
            for (int o : offsets) {
                start = o < cut ? o : start;
            }
            assertEquals(start, e.offset(), "cut at byte " + cut);
            assertEquals(wholeFrames - 1, e.lastGoodStep(), "cut at byte " + cut);
            assertTrue(e.getMessage().startsWith("run.rsr: the recording ends inside the record at byte offset " + start),
                    e.getMessage());
        }
    }

    @Test
    void aFlippedByteInStepSixIsNamedWithItsOffsetAndTheFirstSixStepsStillRead() throws IOException {
        byte[] bytes = Runs.record(true, true);
        int record = recordOffsets(bytes).get(1 + 6);
        bytes[record + 7] ^= 0x40;
        Object[] read = readAsFarAsPossible(bytes);
        assertEquals(6, ((List<?>) read[0]).size(), "steps 0 to 5 replay");
        RecordingException e = (RecordingException) read[1];
        assertFalse(e.truncated());
        assertEquals(record, e.offset());
        assertEquals(5, e.lastGoodStep());
        assertEquals("run.rsr: bad record at byte offset " + record + ", after step 5: the 'F' (frame) record's CRC-32",
                e.getMessage().substring(0, e.getMessage().indexOf(" is ")));
        assertTrue(e.getMessage().endsWith("every record must match its checksum; steps up to 5 are readable"),
                e.getMessage());
    }

    @Test
    void anUnknownRecordKindIsNamed() throws IOException {
        byte[] bytes = Runs.record(true, true);
        int record = recordOffsets(bytes).get(1 + 3);
        bytes[record] = 'X';
        RecordingException e = (RecordingException) readAsFarAsPossible(bytes)[1];
        assertEquals("run.rsr: bad record at byte offset " + record + ", after step 2: record kind 'X' (unknown)"
                + " is not one of 'W', 'F', 'E'; steps up to 2 are readable", e.getMessage());
    }

    @Test
    void anOversizedLengthIsRefusedBeforeAnythingIsAllocated() throws IOException {
        byte[] bytes = Runs.record(true, true);
        int record = recordOffsets(bytes).get(1);
        bytes[record + 1] = 0x7f;
        RecordingException e = (RecordingException) readAsFarAsPossible(bytes)[1];
        assertTrue(e.getMessage().contains("byte offset " + record + ", after step -1: a 'F' (frame) record claims "
                + (0x7f000000 | (bytes[record + 4] & 0xff) | ((bytes[record + 3] & 0xff) << 8) | ((bytes[record + 2] & 0xff) << 16))
                + " bytes of data: a record holds 1 to 16777216; no step is readable"), e.getMessage());
    }

    @Test
    void aFileThatIsNotARecordingSaysSo() throws IOException {
        Path file = dir.resolve("world.xml");
        Files.writeString(file, "<?xml version=\"1.0\"?><world/>");
        RecordingException e = assertThrows(RecordingException.class, () -> RecordingReader.open(file));
        assertEquals(file + " is not a RoboSim recording: it starts with \"<?xml ve\", not the magic \"RoboSimR\"",
                e.getMessage());
    }

    @Test
    void aNewerVersionIsRefusedWithBothVersions() {
        byte[] bytes = Arrays.copyOf("RoboSimR".getBytes(), 12);
        bytes[9] = 2;
        RecordingException e = assertThrows(RecordingException.class,
                () -> new RecordingReader(new ByteArrayInputStream(bytes), "new.rsr"));
        assertEquals("new.rsr is a recording of format version 2: this RoboSim reads versions 1 to 1", e.getMessage());
        assertEquals(8, e.offset());
    }

    @Test
    void aHeaderAloneIsARecordingWithoutItsWorld() throws IOException {
        byte[] bytes = Arrays.copyOf(Runs.record(true, true), RecordingFormat.HEADER_LENGTH);
        RecordingException e = assertThrows(RecordingException.class,
                () -> new RecordingReader(new ByteArrayInputStream(bytes), "empty.rsr"));
        assertTrue(e.getMessage().contains("byte offset 12") && e.getMessage().contains("holds no world record"),
                e.getMessage());
    }

    @Test
    void aDamagedFileReadWholeKeepsItsGoodStepsAndTheProblem() throws IOException {
        byte[] bytes = Runs.record(true, true);
        Path file = dir.resolve("damaged.rsr");
        Files.write(file, Arrays.copyOf(bytes, recordOffsets(bytes).get(1 + 8) + 3));
        Recording r = Recording.read(file);
        assertEquals(8, r.snapshots().size());
        assertTrue(r.problem().truncated());
        assertFalse(r.complete());
        assertEquals(7, r.snapshots().get(7).snapshot().step());
    }
}
