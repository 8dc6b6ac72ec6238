package robosim.experiment;

import java.nio.file.Path;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/** The short {@code report.md} of a results folder: what ran, the summary, the plots, the failures. */
final class Report {
    /** The failed runs the report lists, at most. */
    static final int FAILED_SHOWN = 50;
    /** The metrics the report's table shows, at most. */
    static final int TABLE_METRICS = 6;

    private Report() {
    }

    static String markdown(Experiment e, String fingerprint, ResultsTable table, List<Summary.Row> summary,
                           Map<String, Path> plots, List<Integer> missing, Path out) {
        StringBuilder s = new StringBuilder();
        int failed = (int) table.records().stream().filter(r -> !r.ok()).count();
        s.append("# Experiment ").append(e.name()).append("\n\n");
        s.append("From `").append(e.file().toAbsolutePath().normalize()).append("` (fingerprint ").append(fingerprint)
                .append("), collected ").append(Collector.now()).append(".\n\n");
        s.append(String.format(Locale.ROOT, "%d combination(s) × %d replicate(s) = %d runs: %d done, %d failed, %d"
                        + " missing.%n%n", e.combinations().size(), e.replicates(), e.runCount(), table.records().size(),
                failed, missing.size()));
        s.append("- [results.csv](results.csv): one row per run\n");
        s.append("- [summary.csv](summary.csv): per combination and metric, n, mean, sd and the 95% confidence"
                + " interval of the mean\n");
        s.append("- `runs/`: each run's record, with every robot's figures\n\n");
        List<String> shown = (e.plotMetrics().isEmpty() ? table.numericMetrics()
                : e.plotMetrics().stream().flatMap(List::stream).distinct().toList()).stream()
                .filter(m -> !m.equals(Metrics.WALL_TIME) && !m.equals(Metrics.ROBOTS)).limit(TABLE_METRICS).toList();
        if (!shown.isEmpty() && !summary.isEmpty()) {
            s.append("## Summary\n\nMean [95% CI] (n) over the runs that ran to their end.\n\n|");
            e.factorNames().forEach(f -> s.append(' ').append(f).append(" |"));
            shown.forEach(m -> s.append(' ').append(m).append(" |"));
            s.append("\n|");
            s.append("---|".repeat(e.factorNames().size() + shown.size()));
            s.append('\n');
            for (Map<String, String> c : e.combinations()) {
                s.append('|');
                e.factorNames().forEach(f -> s.append(' ').append(c.get(f)).append(" |"));
                for (String m : shown) {
                    Summary.Row r = summary.stream().filter(x -> x.factors().equals(c) && x.metric().equals(m))
                            .findFirst().orElse(null);
                    s.append(' ').append(cell(r)).append(" |");
                }
                s.append('\n');
            }
            s.append('\n');
        }
        if (!plots.isEmpty()) {
            s.append("## Plots\n\n");
            plots.forEach((m, p) -> s.append("![").append(m.replace("-", " and ")).append("](").append(out.relativize(p).toString()
                    .replace('\\', '/')).append(")\n\n"));
        }
        if (failed > 0) {
            s.append("## Failed runs\n\n");
            table.records().stream().filter(r -> !r.ok()).limit(FAILED_SHOWN).forEach(r -> s.append("- run ")
                    .append(r.index()).append(r.factors().isEmpty() ? "" : " (" + RunFiller.describe(r.factors()) + ")")
                    .append(", seed ").append(r.seed()).append(": ").append(r.failure()).append('\n'));
            if (failed > FAILED_SHOWN) {
                s.append("- and ").append(failed - FAILED_SHOWN).append(" more: results.csv has every one\n");
            }
            s.append('\n');
        }
        List<String> unknown = unknownNames(e, table);
        if (!unknown.isEmpty()) {
            s.append("## Names no run gave\n\n`metrics` or `plot.metrics` name ").append(String.join(", ", unknown))
                    .append(", which no run reported: a typing error, or a metric its programs never reported.\n\n");
        }
        if (!missing.isEmpty()) {
            s.append("## Missing runs\n\nNo record yet: ").append(ranges(missing))
                    .append(". `robosim experiment FILE --out-dir DIR --resume` runs them.\n");
        }
        return s.toString();
    }

    /** @return the metrics the file names to keep or plot that no record has */
    static List<String> unknownNames(Experiment e, ResultsTable table) {
        Set<String> named = new LinkedHashSet<>(e.metrics());
        e.plotMetrics().forEach(named::addAll);
        named.removeIf(n -> table.records().stream().anyMatch(r -> r.metrics().containsKey(n)));
        return table.records().isEmpty() ? List.of() : List.copyOf(named);
    }

    private static String cell(Summary.Row r) {
        if (r == null || r.n() == 0) {
            return "–";
        }
        if (r.n() < 2) {
            return ResultsTable.number(r.mean()) + " (1)";
        }
        return String.format(Locale.ROOT, "%s [%s, %s] (%d)", round(r.mean()), round(r.ciLow()), round(r.ciHigh()), r.n());
    }

    private static String round(double d) {
        return Math.abs(d) >= 100 ? String.format(Locale.ROOT, "%.0f", d) : String.format(Locale.ROOT, "%.3g", d);
    }

    /** @return {@code 3-7, 9} */
    static String ranges(List<Integer> indices) {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < indices.size(); i++) {
            int from = indices.get(i);
            int to = from;
            while (i + 1 < indices.size() && indices.get(i + 1) == to + 1) {
                to = indices.get(++i);
            }
            s.append(s.length() == 0 ? "" : ", ").append(from).append(to > from ? "-" + to : "");
        }
        return s.toString();
    }
}
