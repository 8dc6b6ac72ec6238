package robosim.experiment;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;
import robosim.experiment.Experiment.ProgramTemplate;
import robosim.experiment.Experiment.WorldTemplate;
import robosim.experiment.RunSpec.CommsPlan;
import robosim.experiment.RunSpec.FilePlan;
import robosim.experiment.RunSpec.Link;
import robosim.experiment.RunSpec.MazePlan;
import robosim.experiment.RunSpec.ProgramPlan;
import robosim.protocol.Welcome;

/** Fills an experiment's values in for one run, checking each against its rule. */
final class RunFiller {
    /** The largest maze side, in cells. */
    static final int MAX_MAZE_CELLS = 200;
    /** A number as people write it: digits, a point, an exponent; no hex, no 'f' or 'd'. */
    private static final Pattern DECIMAL =
            Pattern.compile("[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?");
    /** The most robots one program line may start. */
    static final int MAX_ROBOTS = 10_000;

    private final Experiment e;
    private final Map<String, String> values = new LinkedHashMap<>();
    private final String combination;

    private RunFiller(Experiment e, Map<String, String> factors, int index, int replicate, long seed) {
        this.e = e;
        values.putAll(factors);
        values.put("seed", Long.toString(seed));
        values.put("replicate", Integer.toString(replicate));
        values.put("run", Integer.toString(index));
        combination = factors.isEmpty() ? "run " + index : "run " + index + " (" + describe(factors) + ")";
    }

    static RunSpec fill(Experiment e, int index) {
        Map<String, String> factors = e.combinations().get(index / e.replicates());
        int replicate = index % e.replicates() + 1;
        long seed = e.firstSeed() + replicate - 1;
        RunFiller f = new RunFiller(e, factors, index, replicate, seed);
        return new RunSpec(index, factors, replicate, seed, f.world(seed), f.programs(), f.comms(), e.steps());
    }

    /** @return {@code team=4, loss=0.25} */
    static String describe(Map<String, String> factors) {
        StringBuilder s = new StringBuilder();
        factors.forEach((k, v) -> s.append(s.length() == 0 ? "" : ", ").append(k).append('=').append(v));
        return s.toString();
    }

    private RunSpec.WorldPlan world(long seed) {
        WorldTemplate w = e.world();
        Map<String, String> properties = new LinkedHashMap<>();
        w.properties().forEach((k, t) -> {
            String v = text(t);
            if (v.length() > Welcome.MAX_PROPERTY_VALUE) {
                throw error(t, "world property " + k + " is " + v.length() + " characters: a value has at most "
                        + Welcome.MAX_PROPERTY_VALUE);
            }
            properties.put(k, v);
        });
        if (w.file() != null) {
            Path file = e.file().toAbsolutePath().getParent().resolve(text(w.file())).normalize();
            return new FilePlan(file, properties);
        }
        int width = integer(w.cells().get(0), "world.maze.cells", 1, MAX_MAZE_CELLS);
        int height = integer(w.cells().get(w.cells().size() - 1), "world.maze.cells", 1, MAX_MAZE_CELLS);
        if (width * height < 2) {
            throw error(w.cells().get(0), "a maze of 1 cell is given: it has at least 2");
        }
        int cellSize = w.cellSize() == null ? 1500 : integer(w.cellSize(), "world.maze.cellSize", 1000, 100_000);
        long mazeSeed = w.mazeSeed() == null ? seed : longValue(w.mazeSeed(), "world.maze.seed");
        String robotFile = w.robotFile() == null ? "p3dx" : text(w.robotFile());
        // a path is beside the experiment file, as a world file is; a shipped name (p3dx) stays a name
        Path beside = e.file().toAbsolutePath().getParent().resolve(robotFile).normalize();
        if (Files.isRegularFile(beside)) {
            robotFile = beside.toString();
        }
        return new MazePlan(width, height, cellSize, mazeSeed, robotFile, properties);
    }

    private List<ProgramPlan> programs() {
        List<ProgramPlan> out = new ArrayList<>();
        for (ProgramTemplate p : e.programs()) {
            String cls = text(p.className());
            int count = p.count() == null ? -1 : integer(p.count(), "programs' count", 0, MAX_ROBOTS);
            List<String> args = new ArrayList<>();
            for (Template a : p.args()) {
                args.add(text(a));
            }
            Link link = Link.IN_PROCESS;
            if (p.link() != null) {
                String l = text(p.link());
                link = Link.ofFileName(l);
                if (link == null) {
                    throw error(p.link(), "'" + l + "' is given for a program's link: it is in-process"
                            + " (threads of the run's JVM) or jvm (a JVM per robot, over TCP)");
                }
            }
            out.add(new ProgramPlan(cls, count, args, link));
        }
        return out;
    }

    private CommsPlan comms() {
        Experiment.CommsTemplate c = e.comms();
        if (c == null) {
            return CommsPlan.NONE;
        }
        Double range = c.range() == null ? null : number(c.range(), "comms.range", 0, Double.MAX_VALUE);
        Double loss = c.loss() == null ? null : number(c.loss(), "comms.loss", 0, 1);
        Integer latency = c.latency() == null ? null : integer(c.latency(), "comms.latency", 1, 100_000);
        Boolean walls = null;
        if (c.wallsBlock() != null) {
            String v = text(c.wallsBlock());
            if (!v.equals("true") && !v.equals("false")) {
                throw error(c.wallsBlock(), "'" + v + "' is given for comms.wallsBlock: it is true or false");
            }
            walls = Boolean.valueOf(v);
        }
        return new CommsPlan(range, loss, latency, walls);
    }

    private String text(Template t) {
        return t.fill(values);
    }

    private int integer(Template t, String what, int min, int max) {
        return (int) longValue(t, what, min, max);
    }

    private long longValue(Template t, String what) {
        return longValue(t, what, Long.MIN_VALUE, Long.MAX_VALUE);
    }

    private long longValue(Template t, String what, long min, long max) {
        String v = text(t);
        long n;
        try {
            n = Long.parseLong(v.trim());
        } catch (NumberFormatException x) {
            throw error(t, "'" + v + "' is given for " + what + ": it must be a whole number");
        }
        if (n < min || n > max) {
            throw error(t, n + " is given for " + what + ": it must be from " + min
                    + (max == Long.MAX_VALUE || max == Integer.MAX_VALUE ? " up" : " to " + max));
        }
        return n;
    }

    private double number(Template t, String what, double min, double max) {
        String v = text(t);
        double n;
        try {
            if (!DECIMAL.matcher(v.trim()).matches()) {
                throw new NumberFormatException();
            }
            n = Double.parseDouble(v.trim());
        } catch (NumberFormatException x) {
            throw error(t, "'" + v + "' is given for " + what + ": it must be a number, such as 0.25");
        }
        if (!(n >= min && n <= max)) {
            throw error(t, v + " is given for " + what + ": it must be from " + fmt(min)
                    + (max == Double.MAX_VALUE ? " up" : " to " + fmt(max)));
        }
        return n;
    }

    private static String fmt(double d) {
        return d == Math.rint(d) ? Long.toString((long) d) : String.format(Locale.ROOT, "%s", d);
    }

    private ExperimentFileException error(Template t, String rule) {
        String filled = t.names().isEmpty() ? "" : " in " + combination;
        return new ExperimentFileException(e.file(), t.line(), rule + filled);
    }
}
