package robosim.experiment;

import com.fasterxml.jackson.core.JsonToken;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import robosim.experiment.Experiment.Aggregate;
import robosim.experiment.Experiment.CommsTemplate;
import robosim.experiment.Experiment.ProgramTemplate;
import robosim.experiment.Experiment.WorldTemplate;
import robosim.experiment.YamlTree.Mapping;
import robosim.experiment.YamlTree.Node;
import robosim.experiment.YamlTree.Scalar;
import robosim.experiment.YamlTree.Sequence;
import robosim.protocol.Welcome;

/**
 * Reads an experiment file (YAML; the format is in docs/EXPERIMENTS.md). Every rule it breaks is told
 * with the file, the line and the rule; a value that names a factor is checked once each run's value
 * is filled in ({@link Experiment#run}), which {@link #read} does for every run before it returns, so
 * a sweep never starts with a run that cannot.
 */
public final class ExperimentReader {
    private static final List<String> TOP = List.of("name", "world", "programs", "comms", "factors", "cases",
            "replicates", "firstSeed", "steps", "metrics", "aggregate", "plot");

    private final Path file;
    private final Set<String> factorNames = new LinkedHashSet<>();
    private final YamlShapes shapes;

    private ExperimentReader(Path file) {
        this.file = file;
        this.shapes = new YamlShapes(file);
    }

    /**
     * @param file the experiment file
     * @return the experiment, every run's values checked
     * @throws ExperimentFileException naming the file, line and rule
     * @throws IOException             if the file cannot be read
     */
    public static Experiment read(Path file) throws IOException {
        Experiment e = new ExperimentReader(file).experiment(YamlTree.read(file));
        Set<Object> worlds = new HashSet<>();
        for (int i = 0; i < e.runCount(); i++) {
            RunSpec run = e.run(i);
            if (worlds.add(run.world() instanceof RunSpec.MazePlan m ? m.robotFile()
                    : ((RunSpec.FilePlan) run.world()).file())) {
                RunWorlds.check(e, run);
            }
        }
        return e;
    }

    private Experiment experiment(Node root) {
        Mapping top = shapes.mapping(root, "the file");
        shapes.keys(top, TOP, "the file");
        shapes.require(top, "world", "the file");
        shapes.require(top, "programs", "the file");
        String fileName = file.getFileName().toString();
        String name = top.entries().containsKey("name") ? word(top, "name")
                : fileName.replaceFirst("\\.(ya?ml)$", "");
        if (!Experiment.FILE_NAME.matcher(name).matches()) {
            throw new ExperimentFileException(file, top.entries().containsKey("name") ? top.keyLines().get("name") : 0,
                    "'" + name + "' is the experiment's name" + (top.entries().containsKey("name") ? "" : " (the file's)")
                    + ": it names its folder and its cluster job, so it is a letter or digit, then up to 63 letters,"
                    + " digits, '.', '_' or '-'" + (top.entries().containsKey("name") ? "" : "; give name: in the file"));
        }
        List<Map<String, String>> combinations = combinations(top);
        WorldTemplate world = world(shapes.mapping(top.entries().get("world"), "world"));
        List<ProgramTemplate> programs = programs(top.entries().get("programs"));
        if (world.file() == null && programs.get(programs.size() - 1).count() == null) {
            throw new ExperimentFileException(file, top.keyLines().get("programs"), "a program gives no count, but a"
                    + " maze has the robots the programs ask for: give every program a count");
        }
        CommsTemplate comms = top.entries().containsKey("comms") ? comms(shapes.mapping(top.entries().get("comms"), "comms")) : null;
        int replicates = (int) shapes.whole(top, "replicates", 1, 1, 100_000);
        long firstSeed = shapes.whole(top, "firstSeed", 1, 0, Long.MAX_VALUE / 2);
        long steps = shapes.whole(top, "steps", 0, 1, Long.MAX_VALUE);
        if (!top.entries().containsKey("steps")) {
            throw new ExperimentFileException(file, top.line(), "steps is missing: give each run's step limit, e.g."
                    + " steps: 20000, so that a run that never ends of itself ends");
        }
        if ((long) combinations.size() * replicates > Experiment.MAX_RUNS) {
            throw new ExperimentFileException(file, top.keyLines().get("replicates") == null ? top.line()
                    : top.keyLines().get("replicates"), combinations.size() + " combinations of " + replicates
                    + " replicates are more than " + Experiment.MAX_RUNS + " runs");
        }
        List<String> metrics = top.entries().containsKey("metrics") ? names(top.entries().get("metrics"), "metrics")
                : List.of();
        Map<String, Aggregate> aggregates = aggregates(top);
        String plotX = factorNames.isEmpty() ? null : factorNames.iterator().next();
        List<List<String>> plotMetrics = List.of();
        if (top.entries().containsKey("plot")) {
            Mapping plot = shapes.mapping(top.entries().get("plot"), "plot");
            shapes.keys(plot, List.of("x", "metrics"), "plot");
            if (plot.entries().containsKey("x")) {
                plotX = word(plot, "x");
                if (!factorNames.contains(plotX)) {
                    throw new ExperimentFileException(file, plot.keyLines().get("x"), "plot.x is '" + plotX
                            + "': it names one of the factors (" + String.join(", ", factorNames) + ")");
                }
            }
            if (plot.entries().containsKey("metrics")) {
                plotMetrics = plots(plot.entries().get("metrics"));
            }
        }
        return new Experiment(file, name, world, programs, comms, List.copyOf(factorNames), combinations, replicates,
                firstSeed, steps, metrics, aggregates, plotX, plotMetrics);
    }

    private List<Map<String, String>> combinations(Mapping top) {
        boolean grid = top.entries().containsKey("factors");
        boolean cases = top.entries().containsKey("cases");
        if (grid && cases) {
            throw new ExperimentFileException(file, top.keyLines().get("cases"), "factors and cases are both given: give"
                    + " factors for every combination of their values, or cases for the combinations you list");
        }
        if (grid) {
            Mapping factors = shapes.mapping(top.entries().get("factors"), "factors");
            List<String> names = new ArrayList<>();
            List<List<String>> values = new ArrayList<>();
            factors.entries().forEach((name, node) -> {
                factorName(name, factors.keyLines().get(name));
                names.add(name);
                values.add(factorValues(node, name));
            });
            factorNames.addAll(names);
            List<Map<String, String>> out = new ArrayList<>();
            grid(names, values, 0, new LinkedHashMap<>(), out);
            return out;
        }
        if (cases) {
            Node node = top.entries().get("cases");
            if (!(node instanceof Sequence list) || list.items().isEmpty()) {
                throw new ExperimentFileException(file, node.line(), "cases is " + node.kind() + ": it is a list of"
                        + " mappings, each giving every factor a value, e.g. - {team: 4, loss: 0.25}");
            }
            List<Map<String, String>> out = new ArrayList<>();
            for (Node item : list.items()) {
                Mapping c = shapes.mapping(item, "a case");
                if (c.entries().isEmpty()) {
                    throw new ExperimentFileException(file, c.line(), "an empty case: a case gives every factor a value");
                }
                Map<String, String> combination = new LinkedHashMap<>();
                c.entries().forEach((name, v) -> {
                    factorName(name, c.keyLines().get(name));
                    combination.put(name, shapes.scalar(v, "factor " + name));
                });
                if (!out.isEmpty() && !factorNames.equals(combination.keySet())) {
                    throw new ExperimentFileException(file, c.line(), "this case gives " + combination.keySet()
                            + " but the first gave " + factorNames + ": every case gives the same factors");
                }
                factorNames.addAll(combination.keySet());
                if (out.contains(combination)) {
                    throw new ExperimentFileException(file, c.line(), "this case is listed twice: each is listed once"
                            + " (replicates gives a case several runs)");
                }
                out.add(combination);
            }
            return out;
        }
        return List.of(Map.of());
    }

    private static void grid(List<String> names, List<List<String>> values, int k, Map<String, String> at,
                             List<Map<String, String>> out) {
        if (k == names.size()) {
            out.add(new LinkedHashMap<>(at));
            return;
        }
        for (String v : values.get(k)) {
            at.put(names.get(k), v);
            grid(names, values, k + 1, at, out);
        }
        at.remove(names.get(k));
    }

    private void factorName(String name, int line) {
        if (!Experiment.NAME.matcher(name).matches()) {
            throw new ExperimentFileException(file, line, "'" + name + "' is a factor's name: it is a letter, then up"
                    + " to 63 letters, digits or _");
        }
        if (Template.BUILT_IN.contains(name)) {
            throw new ExperimentFileException(file, line, "'" + name + "' is a factor's name, but every run fills in ${"
                    + name + "} itself: call the factor something else");
        }
        if (ResultsTable.RUN_COLUMNS.contains(name) || ResultsTable.SUMMARY_COLUMNS.contains(name)
                || Metrics.BUILT_IN.contains(name)) {
            throw new ExperimentFileException(file, line, "'" + name + "' is a factor's name, but results.csv or"
                    + " summary.csv has a column of that name: call the factor something else (team, not robots)");
        }
    }

    private List<String> factorValues(Node node, String name) {
        if (node instanceof Sequence list) {
            if (list.items().isEmpty()) {
                throw new ExperimentFileException(file, list.line(), "factor " + name + " has no values: give at least one");
            }
            List<String> out = new ArrayList<>();
            for (Node item : list.items()) {
                String v = shapes.scalar(item, "factor " + name);
                if (out.contains(v)) {
                    throw new ExperimentFileException(file, item.line(), "factor " + name + " gives '" + v
                            + "' twice: each value is given once");
                }
                out.add(v);
            }
            return out;
        }
        return List.of(shapes.scalar(node, "factor " + name));
    }

    private WorldTemplate world(Mapping w) {
        shapes.keys(w, List.of("file", "maze", "properties"), "world");
        boolean hasFile = w.entries().containsKey("file");
        boolean hasMaze = w.entries().containsKey("maze");
        if (hasFile == hasMaze) {
            throw new ExperimentFileException(file, w.line(), "world gives " + (hasFile ? "both file and maze" : "neither"
                    + " file nor maze") + ": it gives one, file: a world file (relative to this file), or maze: a"
                    + " generated maze, e.g. maze: {cells: 10}");
        }
        Map<String, Template> properties = new LinkedHashMap<>();
        if (w.entries().containsKey("properties")) {
            Mapping p = shapes.mapping(w.entries().get("properties"), "world.properties");
            p.entries().forEach((k, v) -> {
                if (!Welcome.PROPERTY_NAME.matcher(k).matches()) {
                    throw new ExperimentFileException(file, p.keyLines().get(k), "'" + k + "' is a world property's"
                            + " name: " + Welcome.PROPERTY_NAME_RULE);
                }
                properties.put(k, template(v, "world property " + k));
            });
            if (properties.size() > Welcome.MAX_PROPERTIES) {
                throw new ExperimentFileException(file, p.line(), properties.size() + " world properties are given: a"
                        + " world has at most " + Welcome.MAX_PROPERTIES);
            }
        }
        if (hasFile) {
            return new WorldTemplate(template(w.entries().get("file"), "world.file"), null, null, null, null, properties);
        }
        Mapping m = shapes.mapping(w.entries().get("maze"), "world.maze");
        shapes.keys(m, List.of("cells", "cellSize", "seed", "robotFile"), "world.maze");
        shapes.require(m, "cells", "world.maze");
        Node cellsNode = m.entries().get("cells");
        List<Template> cells = new ArrayList<>();
        if (cellsNode instanceof Sequence s) {
            if (s.items().size() != 2) {
                throw new ExperimentFileException(file, s.line(), "world.maze.cells lists " + s.items().size()
                        + " values: it is N (N × N cells) or [ACROSS, UP]");
            }
            for (Node n : s.items()) {
                cells.add(template(n, "world.maze.cells"));
            }
        } else {
            cells.add(template(cellsNode, "world.maze.cells"));
        }
        return new WorldTemplate(null, cells, optional(m, "cellSize", "world.maze.cellSize"),
                optional(m, "seed", "world.maze.seed"), optional(m, "robotFile", "world.maze.robotFile"), properties);
    }

    private List<ProgramTemplate> programs(Node node) {
        if (!(node instanceof Sequence list) || list.items().isEmpty()) {
            throw new ExperimentFileException(file, node.line(), "programs is " + node.kind() + ": it is a list of"
                    + " programs, e.g. - {class: robosim.examples.goldfinder.GoldFinder, count: 4}");
        }
        List<ProgramTemplate> out = new ArrayList<>();
        for (int i = 0; i < list.items().size(); i++) {
            Mapping p = shapes.mapping(list.items().get(i), "a program");
            shapes.keys(p, List.of("class", "count", "args", "link"), "a program");
            shapes.require(p, "class", "a program");
            Template count = optional(p, "count", "a program's count");
            if (count == null && i < list.items().size() - 1) {
                throw new ExperimentFileException(file, p.line(), "this program gives no count, but programs follow it:"
                        + " only the last may leave count out to take the world's robots that are left");
            }
            List<Template> args = new ArrayList<>();
            if (p.entries().containsKey("args")) {
                Node a = p.entries().get("args");
                if (a instanceof Sequence s) {
                    for (Node n : s.items()) {
                        args.add(template(n, "a program's args"));
                    }
                } else {
                    args.add(template(a, "a program's args"));
                }
            }
            out.add(new ProgramTemplate(template(p.entries().get("class"), "a program's class"), count, args,
                    optional(p, "link", "a program's link")));
        }
        return out;
    }

    private CommsTemplate comms(Mapping c) {
        shapes.keys(c, List.of("range", "loss", "latency", "wallsBlock"), "comms");
        return new CommsTemplate(optional(c, "range", "comms.range"), optional(c, "loss", "comms.loss"),
                optional(c, "latency", "comms.latency"), optional(c, "wallsBlock", "comms.wallsBlock"));
    }

    private Map<String, Aggregate> aggregates(Mapping top) {
        Map<String, Aggregate> out = new LinkedHashMap<>();
        if (!top.entries().containsKey("aggregate")) {
            return out;
        }
        Mapping a = shapes.mapping(top.entries().get("aggregate"), "aggregate");
        a.entries().forEach((name, v) -> {
            metricName(name, a.keyLines().get(name), "aggregate");
            String how = shapes.scalar(v, "aggregate." + name);
            if (!Aggregate.NAMES.contains(how)) {
                throw new ExperimentFileException(file, v.line(), "'" + how + "' is given for aggregate." + name
                        + ": it is mean, sum, min or max");
            }
            out.put(name, Aggregate.valueOf(how.toUpperCase(Locale.ROOT)));
        });
        return out;
    }

    private List<String> names(Node node, String what) {
        if (!(node instanceof Sequence list)) {
            throw new ExperimentFileException(file, node.line(), what + " is " + node.kind() + ": it is a list of"
                    + " metric names, e.g. [steps, foundStep]");
        }
        List<String> out = new ArrayList<>();
        for (Node item : list.items()) {
            String n = shapes.scalar(item, what);
            metricName(n, item.line(), what);
            if (out.contains(n)) {
                throw new ExperimentFileException(file, item.line(), what + " names " + n + " twice");
            }
            out.add(n);
        }
        return out;
    }

    /** {@code [foundStep, [steps, lowerBound]]}: a plot of each name, and of each list's names together. */
    private List<List<String>> plots(Node node) {
        if (!(node instanceof Sequence list)) {
            throw new ExperimentFileException(file, node.line(), "plot.metrics is " + node.kind() + ": it is a list of"
                    + " metric names, each a plot, or lists of names drawn together, e.g. [[foundStep, lowerBound], distance]");
        }
        List<List<String>> out = new ArrayList<>();
        for (Node item : list.items()) {
            List<String> together = item instanceof Sequence ? names(item, "plot.metrics") : List.of(shapes.scalar(item,
                    "plot.metrics"));
            if (together.isEmpty()) {
                throw new ExperimentFileException(file, item.line(), "an empty list in plot.metrics: a plot draws at"
                        + " least one metric");
            }
            together.forEach(n -> metricName(n, item.line(), "plot.metrics"));
            out.add(together);
        }
        return out;
    }

    private void metricName(String name, int line, String what) {
        if (!Metrics.NAME.matcher(name).matches()) {
            throw new ExperimentFileException(file, line, "'" + name + "' is given in " + what + ": a metric's name is"
                    + " a letter, then up to 63 letters, digits, '_', '.' or '-'");
        }
    }

    private String word(Mapping m, String key) {
        return shapes.scalar(m.entries().get(key), key);
    }

    private Template optional(Mapping m, String key, String what) {
        return m.entries().containsKey(key) ? template(m.entries().get(key), what) : null;
    }

    private Template template(Node node, String what) {
        String text = shapes.scalar(node, what);
        Template t = new Template(text, node.line());
        for (String name : t.names()) {
            if (!factorNames.contains(name) && !Template.BUILT_IN.contains(name)) {
                throw new ExperimentFileException(file, node.line(), what + " uses ${" + name + "}, but there is no"
                        + " factor " + name + ": the names are the factors (" + String.join(", ", factorNames)
                        + ") and seed, replicate, run");
            }
        }
        if (node instanceof Scalar s && s.token() == JsonToken.VALUE_STRING && text.contains("${") && t.names().isEmpty()) {
            throw new ExperimentFileException(file, node.line(), what + " has '${' without a closing '}'");
        }
        return t;
    }
}
