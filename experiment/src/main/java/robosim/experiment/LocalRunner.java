package robosim.experiment;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * Runs a sweep's runs on this machine, each in a worker JVM of its own ({@code robosim experiment
 * FILE --run INDEX}, the command a cluster's task runs too), several at once. A JVM per run keeps
 * runs apart (a program's static fields, its threads): a run's row does not depend on the runs
 * before it in the same JVM, so it is the same whatever the parallelism. A worker that dies without
 * writing its record gets a failed record with the reason and its log's last lines; the others go
 * on. Stopped (Ctrl-C, or the JVM told to end), it starts no more workers and stops those running.
 */
public final class LocalRunner {
    /** Makes a worker's command line. */
    @FunctionalInterface
    public interface Workers {
        /**
         * @param run the run's index
         * @return the command that runs it and writes its record
         */
        List<String> command(int run);
    }

    /**
     * How long each run's worker JVM lived, s, and how long its steps took: the difference is what a run
     * costs beyond its simulation.
     *
     * @param run               the run
     * @param workerSeconds     its JVM's life, from start to exit
     * @param simulationSeconds its steps, from the first to the end (0 if it failed)
     */
    public record Timing(int run, double workerSeconds, double simulationSeconds) {
    }

    private final Experiment experiment;
    private final RunExecutor executor;
    private final Path out;
    private final Workers workers;
    private final int parallel;
    private final PrintWriter progress;
    /** The workers running, with their run and start; guarded by this. */
    private final Map<Process, long[]> running = new LinkedHashMap<>();
    private final BlockingQueue<Process> ends = new LinkedBlockingQueue<>();
    private final List<Timing> timings = new ArrayList<>();
    /** Set once the sweep is being stopped: no worker starts after it; guarded by this. */
    private boolean stopping;

    /**
     * @param experiment the experiment
     * @param executor   makes failed records for lost runs
     * @param out        the results folder
     * @param workers    the workers' command lines
     * @param parallel   workers at once, at least 1
     * @param progress   where a line is told as each run ends
     */
    public LocalRunner(Experiment experiment, RunExecutor executor, Path out, Workers workers, int parallel,
                       PrintWriter progress) {
        this.experiment = experiment;
        this.executor = executor;
        this.out = out;
        this.workers = workers;
        this.parallel = Math.max(1, parallel);
        this.progress = progress;
    }

    /**
     * Runs the given runs and waits for them all.
     *
     * @param runs the indices to run, in order
     * @return how many failed
     * @throws IOException          if a worker cannot be started or a record written
     * @throws InterruptedException if interrupted (the workers are stopped)
     */
    public int run(List<Integer> runs) throws IOException, InterruptedException {
        Deque<Integer> pending = new ArrayDeque<>(runs);
        Thread stopWorkers = new Thread(this::stopAll, "experiment-stop-workers");
        Runtime.getRuntime().addShutdownHook(stopWorkers);
        long start = System.nanoTime();
        int done = 0;
        int failed = 0;
        Files.createDirectories(out.resolve("logs"));
        try {
            while (true) {
                synchronized (this) {
                    while (!stopping && running.size() < parallel && !pending.isEmpty()) {
                        startWorker(pending.poll());
                    }
                    if (stopping || running.isEmpty()) {
                        break;
                    }
                }
                Process ended = ends.take();
                long[] runAndStart;
                synchronized (this) {
                    runAndStart = running.remove(ended);
                }
                int index = (int) runAndStart[0];
                RunRecord record = recordOf(index, ended.exitValue());
                Timing t = new Timing(index, (System.nanoTime() - runAndStart[1]) / 1e9, record.simulationSeconds());
                timings.add(t);
                Files.writeString(timingFile(out), String.format(Locale.ROOT, "%d,%.3f,%.3f%n", t.run(),
                        t.workerSeconds(), t.simulationSeconds()), StandardOpenOption.CREATE, StandardOpenOption.APPEND);
                done++;
                if (!record.ok()) {
                    failed++;
                }
                tell(record, done, failed, runs.size(), start);
            }
        } finally {
            stopAll();
            try {
                Runtime.getRuntime().removeShutdownHook(stopWorkers);
            } catch (IllegalStateException e) {
                // the JVM is shutting down: the hook runs anyway
            }
        }
        return failed;
    }

    /**
     * @param out a results folder
     * @return where its local sweeps note each run's worker time and simulation time, a line per run
     *         ({@code run,workerSeconds,simulationSeconds}), for the benchmark
     */
    public static Path timingFile(Path out) {
        return out.resolve("logs").resolve("timing.csv");
    }

    /** @return each finished run's worker time and simulation time, in the order they ended */
    public List<Timing> timings() {
        return List.copyOf(timings);
    }

    private void startWorker(int index) throws IOException {
        Files.deleteIfExists(RunRecords.file(out, index));
        Process p = new ProcessBuilder(workers.command(index)).redirectErrorStream(true)
                .redirectOutput(log(index).toFile()).start();
        running.put(p, new long[] {index, System.nanoTime()});
        p.onExit().thenAccept(ends::add);
    }

    private RunRecord recordOf(int index, int exit) throws IOException {
        RunRecord r = RunRecords.read(out, index);
        if (r != null) {
            return r;
        }
        RunRecord lost = executor.lost(experiment.run(index), "the run's JVM exited with code " + exit
                + " and wrote no record; the end of its log (" + log(index) + "): " + RunRobots.tail(log(index)));
        RunRecords.write(out, lost);
        return lost;
    }

    private Path log(int index) {
        return out.resolve("logs").resolve(String.format(Locale.ROOT, "run-%06d.log", index));
    }

    private void tell(RunRecord r, int done, int failed, int total, long start) {
        double elapsed = (System.nanoTime() - start) / 1e9;
        double eta = done == 0 ? 0 : elapsed / done * (total - done);
        String what = r.factors().isEmpty() ? "" : " (" + RunFiller.describe(r.factors()) + ", seed " + r.seed() + ")";
        Object wall = r.metrics().get(Metrics.WALL_TIME);
        progress.printf(Locale.ROOT, "[%d/%d] run %d%s: %s%s; %d failed; %s, ETA %s%n", done, total, r.index(), what,
                r.ok() ? "ok" : "FAILED: " + r.failure(), wall == null ? "" : " in " + wall + " s", failed,
                duration(elapsed), duration(eta));
        progress.flush();
    }

    /**
     * @param seconds a duration
     * @return it as {@code 45s}, {@code 3m05s} or {@code 2h10m}
     */
    public static String duration(double seconds) {
        long s = Math.round(seconds);
        return s >= 3600 ? String.format(Locale.ROOT, "%dh%02dm", s / 3600, s / 60 % 60)
                : s >= 60 ? String.format(Locale.ROOT, "%dm%02ds", s / 60, s % 60) : s + "s";
    }

    /** Starts no more workers, and stops those running (and the robot JVMs they started). */
    private void stopAll() {
        List<Process> left;
        synchronized (this) {
            stopping = true;
            left = new ArrayList<>(running.keySet());
        }
        for (Process p : left) {
            p.descendants().forEach(ProcessHandle::destroy);
            p.destroy();
        }
        for (Process p : left) {
            try {
                if (!p.waitFor(5, TimeUnit.SECONDS)) {
                    p.descendants().forEach(ProcessHandle::destroyForcibly);
                    p.destroyForcibly();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                p.destroyForcibly();
            }
        }
    }

    /**
     * @param heapBytes each worker's heap
     * @return the workers this machine can run at once: its processors, fewer if its available memory
     *         would not hold them (a worker takes about its heap and a quarter more)
     */
    public static int defaultParallel(long heapBytes) {
        int cores = Runtime.getRuntime().availableProcessors();
        long available = availableMemory();
        if (available <= 0) {
            return cores;
        }
        long perWorker = heapBytes + heapBytes / 4 + (64L << 20);
        return (int) Math.max(1, Math.min(cores, available / perWorker));
    }

    /** @return the memory available to new processes (Linux's MemAvailable), bytes, or -1 if unknown */
    static long availableMemory() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/meminfo"))) {
                if (line.startsWith("MemAvailable:")) {
                    return Long.parseLong(line.replaceAll("\\D", "")) * 1024;
                }
            }
        } catch (IOException | NumberFormatException e) {
            return -1;
        }
        return -1;
    }
}
