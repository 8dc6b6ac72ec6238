package robosim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.concurrent.Callable;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import robosim.experiment.Collector;
import robosim.experiment.Experiment;
import robosim.experiment.ExperimentFileException;
import robosim.experiment.ExperimentFiles;
import robosim.experiment.ExperimentReader;
import robosim.experiment.LocalRunner;
import robosim.experiment.RunExecutor;
import robosim.experiment.RunRecord;
import robosim.experiment.RunRecords;
import robosim.experiment.RunSpec;
import robosim.experiment.Slurm;
import robosim.params.RobotParameterFiles;

/**
 * {@code robosim experiment FILE}: every run of a sweep, on this machine (several at once, each in a
 * JVM of its own) or on a SLURM cluster (a job array), into a results folder; then its tables,
 * plots and report.
 */
@Command(name = "experiment", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Run an experiment: every run of its sweep (factors × replicates), each in a JVM of its own,"
                + " several at once, into --out-dir; then results.csv, summary.csv (means with 95% confidence intervals),"
                + " plots/*.png and report.md.",
                "On a SLURM cluster, --slurm submits the sweep as a job array instead and --collect builds the results"
                        + " once its tasks are done. The file's format is in docs/EXPERIMENTS.md."})
final class ExperimentCommand implements Callable<Integer> {
    /** A heap size as java's -Xmx takes it. */
    private static final Pattern HEAP = Pattern.compile("(\\d{1,6})([kKmMgG])");
    /** A memory size as sbatch's --mem takes it: megabytes unless a unit follows. */
    private static final Pattern SLURM_MEM = Pattern.compile("(\\d{1,9})([kKmMgGtT]?)");

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "FILE", description = "the experiment file (YAML)")
    Path file;

    @Option(names = "--out-dir", paramLabel = "DIR", description = OptionTexts.OUT_DIR
            + "; the results folder, default out/experiments/NAME (NAME the experiment's)")
    Path out;

    @Option(names = "--parallel", paramLabel = "N", description = "runs at once; default as many as the processors,"
            + " fewer if memory would not hold them (each run's JVM takes about --heap)")
    Integer parallel;

    @Option(names = "--resume", description = "go on with a results folder that holds runs of this file: run only"
            + " those with no record, or whose record says they failed")
    boolean resume;

    @Option(names = "--run", paramLabel = "RUNS", description = "run only these runs (e.g. 7 or 0-3,9) and write their"
            + " records, without the tables: what a cluster's task runs. One run runs in this JVM; several, each in"
            + " a JVM of its own")
    String runs;

    @Option(names = "--collect", description = "build results.csv, summary.csv, the plots and report.md from the"
            + " records in --out-dir (after a cluster's tasks), running nothing")
    boolean collect;

    @Option(names = "--record-runs", paramLabel = "RUNS", description = "keep these runs' recordings (e.g. 0,5 or all) in"
            + " DIR/recordings, for robosim replay")
    String record;

    @Option(names = "--heap", defaultValue = "512m", paramLabel = "SIZE", description = "each run's JVM heap (-Xmx);"
            + " default ${DEFAULT-VALUE}")
    String heap;

    @Option(names = "--link", paramLabel = "LINK", description = "how every program's robots reach the Environment,"
            + " whatever the file says: in-process (threads of the run's JVM) or jvm (a JVM per robot, over TCP);"
            + " the rows are the same either way")
    String link;

    @Option(names = {"--classpath", "--cp"}, paramLabel = "PATH", description = OptionTexts.CLASSPATH)
    String classpath;

    @Option(names = "--list", description = "print the sweep's runs, each with its factors and seed, and run nothing")
    boolean list;

    @Option(names = "--slurm", description = "submit the sweep to SLURM as a job array (sbatch), each task running"
            + " --runs-per-task runs on its node into --out-dir, which the nodes must share")
    boolean slurm;

    @Option(names = "--slurm-script", description = "only write the job script (DIR/slurm/NAME.sbatch), to submit"
            + " yourself")
    boolean slurmScript;

    @Option(names = "--wait", description = "with --slurm: wait for every task to end, then collect")
    boolean await;

    @Option(names = "--partition", paramLabel = "NAME", description = "with --slurm: sbatch's --partition")
    String partition;

    @Option(names = "--time", paramLabel = "LIMIT", description = "with --slurm: sbatch's --time, e.g. 01:00:00")
    String time;

    @Option(names = "--cpus-per-task", paramLabel = "N", description = "with --slurm: sbatch's --cpus-per-task; the"
            + " task runs that many runs at once")
    Integer cpusPerTask;

    @Option(names = "--mem", paramLabel = "SIZE", description = "with --slurm: sbatch's --mem, e.g. 2G")
    String mem;

    @Option(names = "--runs-per-task", defaultValue = "1", paramLabel = "N", description = "with --slurm: runs each"
            + " task runs; default ${DEFAULT-VALUE}")
    int runsPerTask;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter err = spec.commandLine().getErr();
        checkFlags();
        try {
            return sweep(spec.commandLine().getOut(), err);
        } catch (IOException x) {
            err.println("robosim experiment: " + x.getMessage());
            err.flush();
            return 1;
        }
    }

    private int sweep(PrintWriter o, PrintWriter err) throws IOException, InterruptedException {
        Experiment e;
        try {
            e = ExperimentReader.read(file);
        } catch (ExperimentFileException x) {
            err.println("robosim experiment: " + x.getMessage());
            return 2;
        } catch (IOException x) {
            err.println("robosim experiment: cannot read " + file + ": " + x);
            return 2;
        }
        String fingerprint = ExperimentFiles.fingerprint(e);
        Path dir = (out != null ? out : Path.of("out", "experiments", e.name())).toAbsolutePath().normalize();
        TreeSet<Integer> recorded = record == null ? new TreeSet<>() : indices("--record-runs", record, e.runCount());
        if (list) {
            for (int i = 0; i < e.runCount(); i++) {
                var r = e.run(i);
                o.printf(Locale.ROOT, "run %d: %s replicate %d, seed %d%n", i, r.factors(), r.replicate(), r.seed());
            }
            o.flush();
            return 0;
        }
        ClassLoader loader;
        try {
            loader = ProgramClasspath.loader(classpath);
        } catch (IllegalArgumentException x) {
            throw new ParameterException(spec.commandLine(), x.getMessage());
        }
        RunExecutor executor = new RunExecutor(e, fingerprint, dir, loader, (cls, robot, port, secret, log, args) ->
                RobotProcesses.start(cls, classpath, robot, port, secret, log, args)).withEveryLink(everyLink());
        if (runs != null) {
            return runOnly(e, fingerprint, dir, executor, indices("--run", runs, e.runCount()), recorded, o, err);
        }
        if (collect) {
            return collect(e, fingerprint, dir, o, err);
        }
        TreeMap<Integer, RunRecord> before = Collector.mine(e, fingerprint, dir);
        if (!before.isEmpty() && !resume) {
            err.println("robosim experiment: " + dir + " already holds " + before.size() + " run record(s) of this"
                    + " experiment: --resume goes on with them, or give another --out-dir");
            return 1;
        }
        List<Integer> pending = new ArrayList<>();
        for (int i = 0; i < e.runCount(); i++) {
            RunRecord r = before.get(i);
            if (r == null || !r.ok()) {
                pending.add(i);
            }
        }
        o.printf(Locale.ROOT, "Experiment %s: %d combination(s) x %d replicate(s) = %d runs; %s into %s%n", e.name(),
                e.combinations().size(), e.replicates(), e.runCount(),
                pending.size() == e.runCount() ? "all to run" : pending.size() + " to run, " + (e.runCount()
                        - pending.size()) + " done before", dir);
        o.flush();
        if (slurm || slurmScript) {
            boolean waited = new ExperimentCluster(e, dir, o, err).submit(slurmRequest(), launcher(),
                    taskOptions(recorded), pending, slurmScript, await);
            return waited ? collect(e, fingerprint, dir, o, err) : 0;
        }
        int workers = Math.min(pending.size(), parallel != null ? parallel : LocalRunner.defaultParallel(heapBytes()));
        o.printf(Locale.ROOT, "Running %d at once, each in a JVM of its own (--heap %s)%n", workers, heap);
        o.flush();
        int failed = new LocalRunner(e, executor, dir, index -> workerCommand(dir, index, recorded), workers, err)
                .run(pending);
        return collect(e, fingerprint, dir, o, err) == 0 && failed == 0 ? 0 : 1;
    }

    private void checkFlags() {
        if (parallel != null && parallel < 1) {
            throw new ParameterException(spec.commandLine(), parallel + " was supplied for --parallel: it must be at least 1");
        }
        if (await && !slurm) {
            throw new ParameterException(spec.commandLine(), "--wait goes with --slurm");
        }
        if (slurm && slurmScript) {
            throw new ParameterException(spec.commandLine(), "--slurm submits and --slurm-script only writes: give one");
        }
        if ((runs != null ? 1 : 0) + (collect ? 1 : 0) + (slurm || slurmScript ? 1 : 0) > 1) {
            throw new ParameterException(spec.commandLine(), "--run, --collect and --slurm each do one thing: give one");
        }
        if (!slurm && !slurmScript && (partition != null || time != null || cpusPerTask != null || mem != null
                || runsPerTask != 1)) {
            throw new ParameterException(spec.commandLine(), "--partition, --time, --cpus-per-task, --mem and"
                    + " --runs-per-task go with --slurm or --slurm-script");
        }
        long heapBytes = heapBytes();
        everyLink();
        memHoldsTheJvms(heapBytes);
    }

    /**
     * Each cluster task runs a launcher and up to {@code min(--cpus-per-task, --runs-per-task)} runs at
     * once, each a JVM with {@code --heap}: a {@code --mem} too small for their heaps fails every task.
     */
    private void memHoldsTheJvms(long heapBytes) {
        Matcher m = mem == null ? null : SLURM_MEM.matcher(mem);
        if (m == null || !m.matches() || Long.parseLong(m.group(1)) == 0) {
            return; // none, one sbatch reads in a way of its own (Slurm.Request checks the characters), or all the node's
        }
        int shift = switch (m.group(2).isEmpty() ? 'm' : Character.toLowerCase(m.group(2).charAt(0))) {
            case 'k' -> 10;
            case 'g' -> 30;
            case 't' -> 40;
            default -> 20;
        };
        long bytes = Long.parseLong(m.group(1)) << shift;
        int atOnce = Math.min(cpusPerTask == null ? 1 : cpusPerTask, runsPerTask);
        long needed = heapBytes * (1 + atOnce);
        if (bytes < needed) {
            throw new ParameterException(spec.commandLine(), String.format(Locale.ROOT, "'%s' was supplied for --mem:"
                    + " each task runs its launcher and %d run(s) at once, each a JVM of --heap %s, so it needs at"
                    + " least %dM; give more, or a smaller --heap", mem, atOnce, heap, needed >> 20));
        }
    }

    private RunSpec.Link everyLink() {
        if (link == null) {
            return null;
        }
        RunSpec.Link every = RunSpec.Link.ofFileName(link);
        if (every == null) {
            throw new ParameterException(spec.commandLine(), "'" + link + "' was supplied for --link: it is"
                    + " in-process or jvm");
        }
        return every;
    }

    private long heapBytes() {
        Matcher m = HEAP.matcher(heap);
        if (!m.matches()) {
            throw new ParameterException(spec.commandLine(), "'" + heap + "' was supplied for --heap: it is a size such"
                    + " as 512m or 2g");
        }
        long n = Long.parseLong(m.group(1));
        long bytes = switch (Character.toLowerCase(m.group(2).charAt(0))) {
            case 'k' -> n << 10;
            case 'm' -> n << 20;
            default -> n << 30;
        };
        if (bytes < (64L << 20)) {
            throw new ParameterException(spec.commandLine(), "'" + heap + "' was supplied for --heap: it must be at least 64m");
        }
        return bytes;
    }

    /** The runs named by a --run or --record value, each checked. */
    private TreeSet<Integer> indices(String option, String value, int count) {
        TreeSet<Integer> out = new TreeSet<>();
        if (value.equals("all") && option.equals("--record-runs")) {
            for (int i = 0; i < count; i++) {
                out.add(i);
            }
            return out;
        }
        String rule = ": it is run indices from 0 to " + (count - 1) + ", e.g. 7 or 0-3,9"
                + (option.equals("--record-runs") ? ", or all" : "");
        for (String part : value.split(",")) {
            String[] ends = part.trim().split("-", -1);
            try {
                if (ends.length > 2) {
                    throw new NumberFormatException();
                }
                int from = Integer.parseInt(ends[0].trim());
                int to = ends.length == 2 ? Integer.parseInt(ends[1].trim()) : from;
                if (from < 0 || to >= count || from > to) {
                    throw new ParameterException(spec.commandLine(), "'" + value + "' was supplied for " + option + rule);
                }
                for (int i = from; i <= to; i++) {
                    out.add(i);
                }
            } catch (NumberFormatException x) {
                throw new ParameterException(spec.commandLine(), "'" + value + "' was supplied for " + option + rule);
            }
        }
        return out;
    }

    private int runOnly(Experiment e, String fingerprint, Path dir, RunExecutor executor, TreeSet<Integer> indices,
                        TreeSet<Integer> recorded, PrintWriter o, PrintWriter err) throws IOException, InterruptedException {
        if (indices.size() == 1) {
            int index = indices.first();
            Path recording = recorded.contains(index) ? dir.resolve("recordings")
                    .resolve(String.format(Locale.ROOT, "run-%06d.rsr", index)) : null;
            RunRecord r = executor.execute(e.run(index), recording);
            RunRecords.write(dir, r);
            o.printf(Locale.ROOT, "run %d: %s%n", index, r.ok() ? "ok, " + r.metrics() : "FAILED: " + r.failure());
            o.flush();
            return 0;
        }
        int workers = Math.min(indices.size(), parallel != null ? parallel : LocalRunner.defaultParallel(heapBytes()));
        new LocalRunner(e, executor, dir, index -> workerCommand(dir, index, recorded), workers, err)
                .run(List.copyOf(indices));
        return 0;
    }

    private int collect(Experiment e, String fingerprint, Path dir, PrintWriter o, PrintWriter err) throws IOException {
        Collector.Collected c = Collector.collect(e, fingerprint, dir);
        o.printf(Locale.ROOT, "Runs: %d of %d recorded, %d failed%s%n", c.done(), e.runCount(), c.failed(),
                c.missing().isEmpty() ? "" : "; " + c.missing().size() + " have no record yet (--resume runs them)");
        o.println("Results: " + c.results());
        o.println("Summary: " + c.summary());
        o.println("Plots: " + c.plots().size() + " in " + dir.resolve("plots"));
        o.println("Report: " + c.report());
        o.flush();
        return c.missing().isEmpty() ? 0 : 1;
    }

    private Slurm.Request slurmRequest() {
        try {
            return new Slurm.Request(partition, time, cpusPerTask, mem, runsPerTask);
        } catch (IllegalArgumentException x) {
            throw new ParameterException(spec.commandLine(), x.getMessage());
        }
    }

    /** @return the options each cluster task's command passes on to the runs it starts */
    private List<String> taskOptions(TreeSet<Integer> recordedRuns) {
        List<String> options = new ArrayList<>(List.of("--heap", heap));
        if (classpath != null) {
            options.addAll(List.of("--classpath", classpath));
        }
        if (!recordedRuns.isEmpty()) {
            options.addAll(List.of("--record-runs", record));
        }
        if (link != null) {
            options.addAll(List.of("--link", link));
        }
        return options;
    }

    /** @return the command that starts this launcher in a new JVM as this one runs: java, heap, classpath, class */
    List<String> launcher() {
        return List.of(RobotProcesses.javaBinary(), "-Xmx" + heap, "-Djava.awt.headless=true",
                "-Drobosim.root=" + RobotParameterFiles.root(), "-cp", System.getProperty("java.class.path"),
                Main.class.getName());
    }

    private List<String> workerCommand(Path dir, int index, TreeSet<Integer> recorded) {
        List<String> cmd = new ArrayList<>(launcher());
        cmd.addAll(List.of("experiment", file.toAbsolutePath().normalize().toString(), "--out-dir", dir.toString(),
                "--run", Integer.toString(index)));
        if (recorded.contains(index)) {
            cmd.addAll(List.of("--record-runs", Integer.toString(index)));
        }
        if (classpath != null) {
            cmd.addAll(List.of("--classpath", classpath));
        }
        if (link != null) {
            cmd.addAll(List.of("--link", link));
        }
        return cmd;
    }
}
