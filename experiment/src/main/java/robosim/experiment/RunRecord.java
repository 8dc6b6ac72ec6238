package robosim.experiment;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What one run gave: its row of results.csv and more. Written as JSON to {@code DIR/runs/} when the
 * run ends ({@link RunRecords}), whether it ran to its end or failed.
 *
 * @param experiment  the experiment's name
 * @param fingerprint the fingerprint of the experiment's runs ({@link ExperimentFiles#fingerprint}): a
 *                    record is of this sweep only if it matches
 * @param index       the run's index
 * @param factors     its factors' values
 * @param replicate   its replicate, from 1
 * @param seed        its seed
 * @param status      {@value #OK} or {@value #FAILED}
 * @param failure     why it failed, or null
 * @param metrics     the run's metrics, by name, in column order: numbers, or text
 * @param robots      each robot's figures
 * @param host        the machine it ran on
 * @param simulationSeconds wall-clock time of its steps alone, from the first to the end, s (0 if it
 *                    did not run): the rest of {@link Metrics#WALL_TIME}, and of its JVM's life, is the
 *                    sweep's overhead (for the benchmark; not a column of results.csv)
 */
public record RunRecord(String experiment, String fingerprint, int index, Map<String, String> factors, int replicate,
                        long seed, String status, String failure, Map<String, Object> metrics, List<RobotFigures> robots,
                        String host, double simulationSeconds) {
    /** A run that ran to its end (whatever the end). */
    public static final String OK = "ok";
    /** A run that could not: a program failed, the world could not be made, the worker died. */
    public static final String FAILED = "failed";

    /** Copies the collections. */
    public RunRecord {
        factors = Collections.unmodifiableMap(new LinkedHashMap<>(factors));
        metrics = Collections.unmodifiableMap(new LinkedHashMap<>(metrics));
        robots = List.copyOf(robots);
    }

    /** @return whether it ran to its end */
    public boolean ok() {
        return OK.equals(status);
    }

    /**
     * A robot's figures in a run.
     *
     * @param name    the robot
     * @param figures its built-in figures and the metrics its program reported, by name
     */
    public record RobotFigures(String name, Map<String, Object> figures) {
        /** Copies the map. */
        public RobotFigures {
            figures = Collections.unmodifiableMap(new LinkedHashMap<>(figures));
        }
    }
}
