package robosim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.TreeMap;
import picocli.CommandLine;
import robosim.experiment.Experiment;
import robosim.experiment.ExperimentFiles;
import robosim.experiment.ExperimentReader;
import robosim.experiment.LocalRunner;
import robosim.experiment.RunRecord;
import robosim.experiment.RunRecords;

/**
 * {@code robosim bench --sweep FILE}: a sweep's throughput on this machine, runs per minute, with its
 * robots on the in-process link and then in JVMs of their own, and the time each run costs beyond its
 * simulation (its JVM's start, the world, the connections, the programs' ends): each run's worker JVM's
 * life less its steps' time, as the sweep noted them ({@link LocalRunner#timingFile}).
 */
final class SweepBench {
    private SweepBench() {
    }

    /** What one sweep took. */
    record Figures(String link, int runs, int failed, int parallel, double wallSeconds, double workerSeconds,
                   double simulatingSeconds) {
        double runsPerMinute() {
            return runs * 60 / wallSeconds;
        }

        double overheadPerRun() {
            return (workerSeconds - simulatingSeconds) / runs;
        }
    }

    /**
     * @param file     the experiment file
     * @param out      where the sweeps' folders go
     * @param parallel runs at once
     * @param links    the links to measure, {@code in-process} and {@code jvm}
     * @return one figure per link
     * @throws IOException if the file cannot be read or a record cannot be
     */
    static List<Figures> run(Path file, Path out, int parallel, List<String> links) throws IOException {
        Experiment e = ExperimentReader.read(file);
        String fingerprint = ExperimentFiles.fingerprint(e);
        return links.stream().map(link -> {
            Path dir = out.resolve("sweep-" + e.name() + "-" + link + "-" + System.nanoTime());
            StringWriter said = new StringWriter();
            CommandLine c = Main.commandLine();
            c.setOut(new PrintWriter(said));
            c.setErr(new PrintWriter(said));
            long start = System.nanoTime();
            c.execute("experiment", file.toString(), "--out-dir", dir.toString(), "--parallel", Integer.toString(parallel),
                    "--link", link);
            double wall = (System.nanoTime() - start) / 1e9;
            try {
                TreeMap<Integer, RunRecord> records = RunRecords.readAll(dir);
                int failed = (int) records.values().stream().filter(r -> !r.ok()).count();
                double simulating = 0;
                double workers = 0;
                for (String line : Files.readAllLines(LocalRunner.timingFile(dir))) {
                    String[] cells = line.split(",");
                    workers += Double.parseDouble(cells[1]);
                    simulating += Double.parseDouble(cells[2]);
                }
                if (records.size() != e.runCount() || !records.values().stream().allMatch(r -> r.fingerprint()
                        .equals(fingerprint))) {
                    throw new IllegalStateException("the sweep left " + records.size() + " of " + e.runCount()
                            + " records: " + said);
                }
                return new Figures(link, records.size(), failed, parallel, wall, workers, simulating);
            } catch (IOException x) {
                throw new IllegalStateException(x);
            }
        }).toList();
    }

    static void print(PrintWriter o, Path file, List<Figures> figures) {
        for (Figures f : figures) {
            o.printf(Locale.ROOT, "sweep %s, links %s: %d runs (%d failed), %d at once, in %.1f s: %.1f runs per minute;"
                            + " per run %.2f s in its JVM, %.2f s of it simulating, %.2f s beyond (JVM start, world,"
                            + " connections, programs' end)%n",
                    file.getFileName(), f.link(), f.runs(), f.failed(), f.parallel(), f.wallSeconds(), f.runsPerMinute(),
                    f.workerSeconds() / f.runs(), f.simulatingSeconds() / f.runs(), f.overheadPerRun());
        }
        o.flush();
    }
}
