package robosim.experiment;

import com.fasterxml.jackson.databind.SequenceWriter;
import com.fasterxml.jackson.dataformat.csv.CsvMapper;
import com.fasterxml.jackson.dataformat.csv.CsvSchema;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.math.BigDecimal;
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
    /** results.csv's columns besides the factors and the metrics. */
    public static final List<String> RUN_COLUMNS = List.of("run", "replicate", "seed", "status", "failure");
    /** summary.csv's columns besides the factors. */
    public static final List<String> SUMMARY_COLUMNS = List.of("metric", "n", "missing", "mean", "sd", "ciLow",
            "ciHigh", "failed");
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
        List<String> header = new ArrayList<>(RUN_COLUMNS.subList(0, 3));
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
        header.addAll(SUMMARY_COLUMNS);
        header.forEach(schema::addColumn);
        List<List<String>> rows = new ArrayList<>();
        for (Summary.Row s : summary) {
            List<String> row = new ArrayList<>();
            for (String f : experiment.factorNames()) {
                row.add(s.factors().get(f));
            }
            row.addAll(List.of(s.metric(), Integer.toString(s.n()), Integer.toString(s.missing()), number(s.mean()),
                    number(s.sd()), number(s.ciLow()), number(s.ciHigh()), Integer.toString(s.failed())));
            rows.add(row);
        }
        write(file, schema.build(), rows);
    }

    private static void write(Path file, CsvSchema schema, List<List<String>> rows) throws IOException {
        AtomicFiles.write(file, out -> {
            try (Writer w = new OutputStreamWriter(out, StandardCharsets.UTF_8);
                 SequenceWriter s = CSV.writerFor(List.class).with(schema).writeValues(w)) {
                for (List<String> row : rows) {
                    s.write(row);
                }
            }
        });
    }

    /** @return a value as a cell: numbers in full, plain (no exponent), whole numbers without ".0" */
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
        if (Double.isInfinite(d)) {
            return d > 0 ? "Infinity" : "-Infinity";
        }
        return BigDecimal.valueOf(d).stripTrailingZeros().toPlainString();
    }
}
