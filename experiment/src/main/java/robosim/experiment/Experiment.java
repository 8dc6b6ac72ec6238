package robosim.experiment;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * An experiment, as its file gives it ({@link ExperimentReader}): a world and robot programs whose
 * values may name factors, the combinations of the factors' values, replicates, a step limit, the
 * metrics to keep and how to plot them. {@link #run(int)} fills in each run.
 *
 * @param file         the experiment file
 * @param name         its name (the file's, without the extension, unless it gives one)
 * @param world        the world, before the factors fill it in
 * @param programs     the programs, before the factors fill them in
 * @param comms        the communications settings, before the factors fill them in
 * @param factorNames  the factors, in the file's order
 * @param combinations each combination of the factors' values: the grid, every combination of
 *                     {@code factors} (the last varying fastest), or the {@code cases} listed
 * @param replicates   runs per combination
 * @param firstSeed    the first replicate's seed
 * @param steps        each run's step limit
 * @param metrics      the metrics to keep, or empty for all
 * @param aggregates   how the robots' values of a metric the programs report make the run's: by name
 * @param plotX        the factor the plots put along x
 * @param plotMetrics  the plots, each the metrics it draws together (most draw one), or empty for a plot
 *                     of each numeric metric kept
 */
public record Experiment(Path file, String name, WorldTemplate world, List<ProgramTemplate> programs,
                         CommsTemplate comms, List<String> factorNames, List<Map<String, String>> combinations,
                         int replicates, long firstSeed, long steps, List<String> metrics,
                         Map<String, Aggregate> aggregates, String plotX, List<List<String>> plotMetrics) {
    /** A factor's or metric's name. */
    static final Pattern NAME = Pattern.compile("[A-Za-z][A-Za-z0-9_]{0,63}");
    /** An experiment's name: its folder's and its cluster job's. */
    static final Pattern FILE_NAME = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._-]{0,63}");
    /** The most runs a sweep may have. */
    public static final int MAX_RUNS = 1_000_000;

    /** Copies the collections. */
    public Experiment {
        programs = List.copyOf(programs);
        factorNames = List.copyOf(factorNames);
        List<Map<String, String>> copies = new ArrayList<>();
        for (Map<String, String> c : combinations) {
            copies.add(Collections.unmodifiableMap(new LinkedHashMap<>(c)));
        }
        combinations = List.copyOf(copies);
        metrics = List.copyOf(metrics);
        aggregates = Collections.unmodifiableMap(new LinkedHashMap<>(aggregates));
        plotMetrics = plotMetrics.stream().map(List::copyOf).toList();
    }

    /** How the robots' values of a reported metric make the run's one value. */
    public enum Aggregate {
        /** The mean over the robots that reported it. */
        MEAN,
        /** Their sum. */
        SUM,
        /** The least. */
        MIN,
        /** The greatest. */
        MAX;

        static final Set<String> NAMES = Set.of("mean", "sum", "min", "max");
    }

    /**
     * The world, its values as written.
     *
     * @param file       a world file, or null for a maze
     * @param cells      the maze's cells across and up (null for a file)
     * @param cellSize   the maze's cell size, mm
     * @param mazeSeed   the maze's seed
     * @param robotFile  the maze robots' parameter file
     * @param properties world properties to set
     */
    public record WorldTemplate(Template file, List<Template> cells, Template cellSize, Template mazeSeed,
                                Template robotFile, Map<String, Template> properties) {
    }

    /**
     * A program, its values as written.
     *
     * @param className the class
     * @param count     how many robots run it, or null for the world's robots not taken before
     * @param args      its arguments
     * @param link      {@code in-process} or {@code jvm}
     */
    public record ProgramTemplate(Template className, Template count, List<Template> args, Template link) {
    }

    /**
     * The communications settings, each null to keep the world's.
     *
     * @param range      mm
     * @param loss       0 to 1
     * @param latency    steps
     * @param wallsBlock true or false
     */
    public record CommsTemplate(Template range, Template loss, Template latency, Template wallsBlock) {
    }

    /** @return how many runs the sweep has */
    public int runCount() {
        return combinations.size() * replicates;
    }

    /**
     * @param index the run's index, from 0
     * @return the run
     * @throws IndexOutOfBoundsException if there is no such run
     * @throws ExperimentFileException   if a value the factors fill in breaks its rule
     */
    public RunSpec run(int index) {
        if (index < 0 || index >= runCount()) {
            throw new IndexOutOfBoundsException("run " + index + " was asked for: experiment " + name + " has runs 0 to "
                    + (runCount() - 1));
        }
        return RunFiller.fill(this, index);
    }
}
