package robosim.experiment;

import java.awt.BasicStroke;
import java.awt.Color;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.jfree.chart.ChartUtils;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.axis.SymbolAxis;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYErrorRenderer;
import org.jfree.data.xy.YIntervalSeries;
import org.jfree.data.xy.YIntervalSeriesCollection;

/**
 * One PNG per plot ({@code plot.metrics}: a metric, or several drawn together): each metric's mean
 * against the main factor ({@code plot.x}), with the 95% confidence interval as a bar, one line per
 * combination of the other factors. Drawn with JFreeChart, headless.
 */
public final class Plots {
    /** The plots' size, pixels. */
    static final int WIDTH = 800;
    static final int HEIGHT = 500;
    private static final Color[] COLORS = {new Color(0x1f77b4), new Color(0xd62728), new Color(0x2ca02c),
            new Color(0xff7f0e), new Color(0x9467bd), new Color(0x8c564b), new Color(0xe377c2), new Color(0x7f7f7f)};

    private Plots() {
    }

    /**
     * @param experiment the experiment
     * @param table      its results
     * @param summary    its summary
     * @param dir        the folder the PNG files go to
     * @return the files written, by plot: its metrics' names joined by '-'
     * @throws IOException if one cannot be written
     */
    public static Map<String, Path> write(Experiment experiment, ResultsTable table, List<Summary.Row> summary,
                                          Path dir) throws IOException {
        Map<String, Path> out = new LinkedHashMap<>();
        String x = experiment.plotX();
        if (x == null) {
            return out;
        }
        Files.createDirectories(dir);
        // the plots of an earlier collection go: the file's plots may have changed since
        try (var old = Files.newDirectoryStream(dir, "*.png")) {
            for (Path p : old) {
                Files.delete(p);
            }
        }
        List<List<String>> plots = experiment.plotMetrics().isEmpty()
                ? table.numericMetrics().stream().map(List::of).toList() : experiment.plotMetrics();
        for (List<String> metrics : plots) {
            List<Summary.Row> rows = summary.stream().filter(r -> metrics.contains(r.metric()) && r.n() > 0).toList();
            if (rows.isEmpty()) {
                continue;
            }
            String name = String.join("-", metrics);
            Path file = dir.resolve(name + ".png");
            JFreeChart chart = chart(experiment, metrics, rows);
            AtomicFiles.write(file, o -> ChartUtils.writeChartAsPNG(o, chart, WIDTH, HEIGHT));
            out.put(name, file);
        }
        return out;
    }

    private static JFreeChart chart(Experiment experiment, List<String> metrics, List<Summary.Row> rows) {
        String x = experiment.plotX();
        List<String> xs = new ArrayList<>();
        for (Map<String, String> c : experiment.combinations()) {
            if (!xs.contains(c.get(x))) {
                xs.add(c.get(x));
            }
        }
        boolean numeric = xs.stream().allMatch(Plots::isNumber);
        YIntervalSeriesCollection data = new YIntervalSeriesCollection();
        Map<String, YIntervalSeries> series = new LinkedHashMap<>();
        for (Summary.Row r : rows) {
            Map<String, String> others = new LinkedHashMap<>(r.factors());
            others.remove(x);
            String key = metrics.size() == 1 ? (others.isEmpty() ? r.metric() : RunFiller.describe(others))
                    : others.isEmpty() ? r.metric() : r.metric() + ", " + RunFiller.describe(others);
            YIntervalSeries s = series.computeIfAbsent(key, k -> {
                YIntervalSeries made = new YIntervalSeries(k);
                data.addSeries(made);
                return made;
            });
            double at = (numeric ? Double.parseDouble(r.factors().get(x)) : xs.indexOf(r.factors().get(x)))
                    + dodge(new ArrayList<>(series.keySet()).indexOf(key), seriesCount(rows, x, metrics.size()), xs,
                    numeric);
            double low = Double.isNaN(r.ciLow()) ? r.mean() : r.ciLow();
            double high = Double.isNaN(r.ciHigh()) ? r.mean() : r.ciHigh();
            s.add(at, r.mean(), low, high);
        }
        ValueAxis xAxis = numeric ? new NumberAxis(x) : new SymbolAxis(x, xs.toArray(String[]::new));
        if (xAxis instanceof NumberAxis n) {
            n.setAutoRangeIncludesZero(false);
            if (xs.stream().allMatch(v -> v.matches("-?\\d+"))) {
                n.setStandardTickUnits(NumberAxis.createIntegerTickUnits());
            }
        }
        String what = String.join(", ", metrics);
        NumberAxis yAxis = new NumberAxis(what + " (mean, 95% CI)");
        yAxis.setAutoRangeIncludesZero(true);
        XYErrorRenderer renderer = new XYErrorRenderer();
        renderer.setDefaultLinesVisible(true);
        renderer.setDrawXError(false);
        renderer.setErrorStroke(new BasicStroke(1.5f));
        for (int i = 0; i < series.size(); i++) {
            renderer.setSeriesPaint(i, COLORS[i % COLORS.length]);
            renderer.setSeriesStroke(i, new BasicStroke(2f));
        }
        XYPlot plot = new XYPlot(data, xAxis, yAxis, renderer);
        plot.setBackgroundPaint(Color.WHITE);
        plot.setDomainGridlinePaint(new Color(0xdddddd));
        plot.setRangeGridlinePaint(new Color(0xdddddd));
        JFreeChart chart = new JFreeChart(experiment.name() + ": " + String.join(" and ", metrics) + " by " + x,
                JFreeChart.DEFAULT_TITLE_FONT, plot, series.size() > 1 || !series.containsKey(metrics.get(0)));
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    /** @return how many lines the plot has: combinations of the factors other than x */
    private static int seriesCount(List<Summary.Row> rows, String x, int metrics) {
        return (int) rows.stream().map(r -> {
            Map<String, String> others = new LinkedHashMap<>(r.factors());
            others.remove(x);
            others.put("", metrics > 1 ? r.metric() : "");
            return others;
        }).distinct().count();
    }

    /**
     * Lines side by side a little apart, so that equal means do not hide each other's bars: a
     * fiftieth of the x range between neighbours.
     */
    private static double dodge(int line, int lines, List<String> xs, boolean numeric) {
        if (lines < 2) {
            return 0;
        }
        double span = numeric ? xs.stream().mapToDouble(Double::parseDouble).max().orElse(1)
                - xs.stream().mapToDouble(Double::parseDouble).min().orElse(0) : xs.size() - 1;
        double step = (span > 0 ? span : 1) / 50;
        return (line - (lines - 1) / 2.0) * step;
    }

    private static boolean isNumber(String s) {
        try {
            Double.parseDouble(s);
            return true;
        } catch (NumberFormatException e) {
            return false;
        }
    }
}
