package robosim.experiment;

import com.fasterxml.jackson.databind.SequenceWriter;
import com.fasterxml.jackson.dataformat.csv.CsvMapper;
import com.fasterxml.jackson.dataformat.csv.CsvSchema;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * The results of a sweep as tables: {@code results.csv}, one row per run (its index, replicate, seed,
 * factors, status and metrics), and {@code summary.csv}, one row per combination and metric
 * ({@link Summary}). Written through Jackson's CSV format, which quotes and escapes as RFC 4180 says.
 */
public final class ResultsTable {
    private static final CsvMapper CSV = new CsvMapper();

    private final Experiment experiment;
    private final List<RunRecord> records;
    private final List<String> metrics;

    /**
     * @param experiment the experiment
     * @param records    its runs' records, in index order
     */
    public ResultsTable(Experiment experiment, Collection<RunRecord> records) {
        this.experiment = experiment;
        this.records = List.copyOf(records);
        this.metrics = metricColumns();
    }

    /** @return the records, in index order */
    public List<RunRecord> records() {
        return records;
    }

    /** @return the metric columns: those the experiment keeps, or every one a run gave, built-in first */
    public List<String> metrics() {
        return metrics;
    }

    private List<String> metricColumns() {
        if (!experiment.metrics().isEmpty()) {
            return experiment.metrics();
        }
        Set<String> all = new LinkedHashSet<>();
        for (RunRecord r : records) {
            all.addAll(r.metrics().keySet());
        }
        List<String> out = new ArrayList<>();
        for (String b : Metrics.BUILT_IN) {
            if (all.remove(b)) {
                out.add(b);
            }
        }
        // the programs' own after the built-in ones, wall time last
        out.addAll(all);
        if (out.remove(Metrics.WALL_TIME)) {
            out.add(Metrics.WALL_TIME);
        }
        return out;
    }

    /** @return the metrics every run that gave them gave as numbers, in column order */
    public List<String> numericMetrics() {
        List<String> out = new ArrayList<>();
        for (String m : metrics) {
            boolean any = false;
            boolean numeric = true;
            for (RunRecord r : records) {
                Object v = r.metrics().get(m);
                if (v != null) {
                    any = true;
                    numeric &= v instanceof Number;
                }
            }
            if (any && numeric) {
                out.add(m);
            }
        }
        return out;
    }

    /**
     * Writes results.csv.
     *
     * @param file where
     * @throws IOException if it cannot be written
     */
    public void writeResults(Path file) throws IOException {
        CsvSchema.Builder schema = CsvSchema.builder().setUseHeader(true);
        List<String> header = new ArrayList<>(List.of("run", "replicate", "seed"));
        header.addAll(experiment.factorNames());
        header.add("status");
        header.addAll(metrics);
        header.add("failure");
        header.forEach(schema::addColumn);
        List<List<String>> rows = new ArrayList<>();
        for (RunRecord r : records) {
            List<String> row = new ArrayList<>(List.of(Integer.toString(r.index()), Integer.toString(r.replicate()),
                    Long.toString(r.seed())));
            for (String f : experiment.factorNames()) {
                row.add(r.factors().getOrDefault(f, ""));
            }
            row.add(r.status());
            for (String m : metrics) {
                row.add(text(r.metrics().get(m)));
            }
            row.add(r.failure() == null ? "" : r.failure());
            rows.add(row);
        }
        write(file, schema.build(), rows);
    }

    /**
     * Writes summary.csv.
     *
     * @param file    where
     * @param summary the summary's rows
     * @throws IOException if it cannot be written
     */
    public void writeSummary(Path file, List<Summary.Row> summary) throws IOException {
        CsvSchema.Builder schema = CsvSchema.builder().setUseHeader(true);
        List<String> header = new ArrayList<>(experiment.factorNames());
        header.addAll(List.of("metric", "n", "mean", "sd", "ciLow", "ciHigh", "failed"));
        header.forEach(schema::addColumn);
        List<List<String>> rows = new ArrayList<>();
        for (Summary.Row s : summary) {
            List<String> row = new ArrayList<>();
            for (String f : experiment.factorNames()) {
                row.add(s.factors().get(f));
            }
            row.addAll(List.of(s.metric(), Integer.toString(s.n()), number(s.mean()), number(s.sd()),
                    number(s.ciLow()), number(s.ciHigh()), Integer.toString(s.failed())));
            rows.add(row);
        }
        write(file, schema.build(), rows);
    }

    private static void write(Path file, CsvSchema schema, List<List<String>> rows) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        Path tmp = Files.createTempFile(file.toAbsolutePath().getParent(), "." + file.getFileName(), ".tmp");
        try {
            try (Writer w = Files.newBufferedWriter(tmp, StandardCharsets.UTF_8);
                 SequenceWriter s = CSV.writerFor(List.class).with(schema).writeValues(w)) {
                for (List<String> row : rows) {
                    s.write(row);
                }
            }
            Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    /** @return a value as a cell: numbers as Java writes them shortest, whole numbers without ".0" */
    static String text(Object v) {
        if (v == null) {
            return "";
        }
        if (v instanceof Double d) {
            return number(d);
        }
        return v.toString();
    }

    static String number(double d) {
        if (Double.isNaN(d)) {
            return "";
        }
        if (d == Math.rint(d) && Math.abs(d) < 1e15) {
            return Long.toString((long) d);
        }
        return String.format(Locale.ROOT, "%.6g", d).replaceFirst("(\\.\\d*?)0+(e|$)", "$1$2").replaceFirst("\\.(e|$)", "$1");
    }
}
