package robosim.experiment;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The run records of a results folder, one JSON file per run in {@code DIR/runs/}, each written
 * whole or not at all ({@link AtomicFiles}), so that a worker killed halfway leaves no half record
 * and a folder shared by many workers (a cluster's) never holds a torn one.
 */
public final class RunRecords {
    private static final Pattern FILE = Pattern.compile("run-(\\d{6,})\\.json");
    private static final ObjectMapper JSON = new ObjectMapper()
            .enable(SerializationFeature.INDENT_OUTPUT)
            .disable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES);

    private RunRecords() {
    }

    /**
     * @param out   the results folder
     * @param index a run's index
     * @return where its record goes
     */
    public static Path file(Path out, int index) {
        return out.resolve("runs").resolve(String.format(Locale.ROOT, "run-%06d.json", index));
    }

    /**
     * Writes a run's record, replacing any before it.
     *
     * @param out    the results folder
     * @param record the record
     * @throws IOException if it cannot be written
     */
    public static void write(Path out, RunRecord record) throws IOException {
        AtomicFiles.write(file(out, record.index()), o -> JSON.writeValue(o, record));
    }

    /**
     * @param out   the results folder
     * @param index a run's index
     * @return its record, or null if it has none
     * @throws IOException if it cannot be read, naming the file
     */
    public static RunRecord read(Path out, int index) throws IOException {
        Path f = file(out, index);
        if (!Files.exists(f)) {
            return null;
        }
        try {
            return JSON.readValue(f.toFile(), RunRecord.class);
        } catch (JsonProcessingException e) {
            throw new IOException(f + " is no run record: " + e.getOriginalMessage(), e);
        }
    }

    /**
     * Reads every record of a folder, in index order.
     *
     * @param out the results folder
     * @return the records by index (empty if it has none)
     * @throws IOException if a record cannot be read, naming the file
     */
    public static TreeMap<Integer, RunRecord> readAll(Path out) throws IOException {
        TreeMap<Integer, RunRecord> records = new TreeMap<>();
        Path dir = out.resolve("runs");
        if (!Files.isDirectory(dir)) {
            return records;
        }
        List<Path> files = new ArrayList<>();
        try (DirectoryStream<Path> s = Files.newDirectoryStream(dir, "run-*.json")) {
            s.forEach(files::add);
        }
        for (Path f : files) {
            Matcher m = FILE.matcher(f.getFileName().toString());
            if (!m.matches()) {
                continue;
            }
            try {
                RunRecord r = JSON.readValue(f.toFile(), RunRecord.class);
                records.put(r.index(), r);
            } catch (JsonProcessingException e) {
                throw new IOException(f + " is no run record: " + e.getOriginalMessage(), e);
            }
        }
        return records;
    }
}
