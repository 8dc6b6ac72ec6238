package robosim.experiment;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.apache.commons.statistics.descriptive.Mean;
import org.apache.commons.statistics.descriptive.StandardDeviation;
import org.apache.commons.statistics.distribution.TDistribution;

/**
 * Per combination of the factors and per numeric metric: n, the mean, the sample standard deviation
 * and the 95% confidence interval of the mean (Student's t with n − 1 degrees of freedom, from
 * Apache Commons Statistics), over the runs that ran to their end.
 */
public final class Summary {
    /** The interval's confidence. */
    public static final double CONFIDENCE = 0.95;

    private Summary() {
    }

    /**
     * A metric over the runs of one combination.
     *
     * @param factors the combination
     * @param metric  the metric
     * @param n       the runs that ran to their end and gave it a value
     * @param missing the runs that ran to their end without a value for it (the gold not found, so no
     *                {@code foundStep}): the mean is of the others, which may not be all of a kind
     * @param mean    their mean
     * @param sd      their sample standard deviation (NaN if n is under 2)
     * @param ciLow   the interval's low end (NaN if n is under 2)
     * @param ciHigh  its high end (NaN if n is under 2)
     * @param failed  the combination's runs that failed
     */
    public record Row(Map<String, String> factors, String metric, int n, int missing, double mean, double sd,
                      double ciLow, double ciHigh, int failed) {
    }

    /**
     * @param experiment the experiment
     * @param table      its results
     * @return the rows: combinations in the experiment's order, each with its numeric metrics in column order
     */
    public static List<Row> of(Experiment experiment, ResultsTable table) {
        List<String> numeric = table.numericMetrics();
        List<Row> out = new ArrayList<>();
        for (Map<String, String> combination : experiment.combinations()) {
            List<RunRecord> runs = table.records().stream().filter(r -> r.factors().equals(combination)).toList();
            int failed = (int) runs.stream().filter(r -> !r.ok()).count();
            for (String metric : numeric) {
                List<Double> values = new ArrayList<>();
                int missing = 0;
                for (RunRecord r : runs) {
                    if (r.ok() && r.metrics().get(metric) instanceof Number n) {
                        values.add(n.doubleValue());
                    } else if (r.ok()) {
                        missing++;
                    }
                }
                out.add(row(combination, metric, values, missing, failed));
            }
        }
        return out;
    }

    static Row row(Map<String, String> combination, String metric, List<Double> values, int missing, int failed) {
        int n = values.size();
        double[] v = values.stream().mapToDouble(Double::doubleValue).toArray();
        double mean = n == 0 ? Double.NaN : Mean.of(v).getAsDouble();
        double sd = n < 2 ? Double.NaN : StandardDeviation.of(v).getAsDouble();
        double half = n < 2 ? Double.NaN
                : TDistribution.of(n - 1).inverseCumulativeProbability(1 - (1 - CONFIDENCE) / 2) * sd / Math.sqrt(n);
        return new Row(new LinkedHashMap<>(combination), metric, n, missing, mean, sd, mean - half, mean + half, failed);
    }
}
