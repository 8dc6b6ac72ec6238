package robosim.experiment;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Builds a results folder's tables, plots and report from its run records: {@code results.csv},
 * {@code summary.csv}, {@code plots/*.png} and {@code report.md}. Runs after a local sweep, and by
 * {@code --collect} once a cluster's tasks are done.
 */
public final class Collector {
    private Collector() {
    }

    /**
     * What a collection found and wrote.
     *
     * @param done    records of this experiment
     * @param failed  of which failed
     * @param missing runs with no record
     * @param results results.csv
     * @param summary summary.csv
     * @param plots   the plots by metric
     * @param report  report.md
     */
    public record Collected(int done, int failed, List<Integer> missing, Path results, Path summary,
                            Map<String, Path> plots, Path report) {
    }

    /**
     * @param experiment  the experiment
     * @param fingerprint its file's fingerprint
     * @param out         the results folder
     * @return what was found and written
     * @throws IOException if a record cannot be read or a file written; or if the folder holds records of
     *                     other runs
     */
    public static Collected collect(Experiment experiment, String fingerprint, Path out) throws IOException {
        TreeMap<Integer, RunRecord> records = mine(experiment, fingerprint, out);
        List<Integer> missing = new ArrayList<>();
        for (int i = 0; i < experiment.runCount(); i++) {
            if (!records.containsKey(i)) {
                missing.add(i);
            }
        }
        ResultsTable table = new ResultsTable(experiment, records.values());
        List<Summary.Row> summary = Summary.of(experiment, table);
        Path results = out.resolve("results.csv");
        Path summaryFile = out.resolve("summary.csv");
        table.writeResults(results);
        table.writeSummary(summaryFile, summary);
        Map<String, Path> plots = Plots.write(experiment, table, summary, out.resolve("plots"));
        int failed = (int) records.values().stream().filter(r -> !r.ok()).count();
        Path report = out.resolve("report.md");
        AtomicFiles.write(report, Report.markdown(experiment, fingerprint, table, summary, plots, missing, out));
        return new Collected(records.size(), failed, missing, results, summaryFile, plots, report);
    }

    /**
     * @param experiment  the experiment
     * @param fingerprint its file's fingerprint
     * @param out         the results folder
     * @return its records, by index
     * @throws IOException if one cannot be read, or one is of other runs or has an index the experiment
     *                     does not have
     */
    public static TreeMap<Integer, RunRecord> mine(Experiment experiment, String fingerprint, Path out)
            throws IOException {
        TreeMap<Integer, RunRecord> records = RunRecords.readAll(out);
        for (RunRecord r : records.values()) {
            if (!r.fingerprint().equals(fingerprint) || r.index() >= experiment.runCount()) {
                throw new IOException(out + " holds runs of another experiment, or of this file before its runs"
                        + " changed (run " + r.index() + " of " + r.experiment() + ", fingerprint " + r.fingerprint()
                        + "; this file's is " + fingerprint + "): give a new --out-dir, or remove the folder");
            }
        }
        return records;
    }

    /** @return now, to the second, for the report */
    static String now() {
        return Instant.now().truncatedTo(ChronoUnit.SECONDS).toString();
    }
}
