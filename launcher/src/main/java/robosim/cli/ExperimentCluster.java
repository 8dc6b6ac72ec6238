package robosim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import robosim.experiment.Experiment;
import robosim.experiment.LocalRunner;
import robosim.experiment.RunRecord;
import robosim.experiment.RunRecords;
import robosim.experiment.Slurm;
import robosim.params.RobotParameterFiles;

/** {@code robosim experiment --slurm} and {@code --slurm-script}: a sweep's job array, written, submitted, followed. */
final class ExperimentCluster {
    /** How long squeue may keep failing before the wait gives up, s. */
    static final int SQUEUE_PATIENCE_S = 120;

    private final Experiment experiment;
    private final Path dir;
    private final PrintWriter out;
    private final PrintWriter err;

    ExperimentCluster(Experiment experiment, Path dir, PrintWriter out, PrintWriter err) {
        this.experiment = experiment;
        this.dir = dir;
        this.out = out;
        this.err = err;
    }

    /**
     * Writes the job script and, unless only the script is asked for, submits it.
     *
     * @param request    what the job asks of the cluster
     * @param launcher   the command that starts the launcher on a node
     * @param options    the options each task passes on
     * @param pending    the runs to do
     * @param scriptOnly whether only to write the script
     * @param await      whether to follow the job until it leaves the queue
     * @return whether the job was followed to its end, so that the results can be collected
     * @throws IOException if the script cannot be written, or sbatch or squeue fail
     * @throws InterruptedException if interrupted while waiting
     */
    boolean submit(Slurm.Request request, List<String> launcher, List<String> options, List<Integer> pending,
                   boolean scriptOnly, boolean await) throws IOException, InterruptedException {
        String again = bin() + " experiment " + experiment.file().toAbsolutePath().normalize() + " --out-dir " + dir;
        if (pending.isEmpty()) {
            out.println("Every run has its record: nothing to submit");
            out.flush();
            return true;
        }
        Path script = Slurm.writeScript(experiment, launcher, dir, request, pending, options);
        out.println("Job script: " + script);
        if (scriptOnly) {
            out.println("Submit it with: sbatch " + script);
            out.println("Then: " + again + " --collect");
            out.flush();
            return false;
        }
        // the runs go again: a failed record of one of them must not count as done while the job runs
        for (int i : pending) {
            Files.deleteIfExists(RunRecords.file(dir, i));
        }
        String job = Slurm.submit(script);
        out.printf(Locale.ROOT, "Submitted job %s: %d task(s)%n", job, Slurm.tasks(pending.size(), request.runsPerTask()));
        if (!await) {
            out.println("When its tasks are done: " + again + " --collect");
            out.flush();
            return false;
        }
        out.printf(Locale.ROOT, "Waiting for job %s to leave the queue (Ctrl-C stops the waiting, not the job:"
                + " scancel %s stops it, --collect builds the results later)%n", job, job);
        out.flush();
        follow(job, pending);
        return true;
    }

    /** Follows a job until it leaves the queue, telling how many of its runs have their records as they come. */
    private void follow(String job, List<Integer> pending) throws IOException, InterruptedException {
        long start = System.nanoTime();
        Set<Integer> seen = new HashSet<>();
        int failed = 0;
        int told = -1;
        long squeueFailing = 0;
        while (true) {
            boolean queued;
            try {
                queued = Slurm.queued(job);
                squeueFailing = 0;
            } catch (IOException x) {
                long now = System.nanoTime();
                squeueFailing = squeueFailing == 0 ? now : squeueFailing;
                if ((now - squeueFailing) / 1e9 > SQUEUE_PATIENCE_S) {
                    throw new IOException("squeue has failed for " + SQUEUE_PATIENCE_S + " s (" + x.getMessage()
                            + "); job " + job + " may still run: --collect builds the results once it is done", x);
                }
                queued = true;
            }
            // only the runs not yet seen are read: a shared folder is slow
            for (int i : pending) {
                if (!seen.contains(i) && Files.exists(RunRecords.file(dir, i))) {
                    RunRecord r = RunRecords.read(dir, i);
                    if (r != null) {
                        seen.add(i);
                        failed += r.ok() ? 0 : 1;
                    }
                }
            }
            if (seen.size() != told) {
                double elapsed = (System.nanoTime() - start) / 1e9;
                err.printf(Locale.ROOT, "job %s: %d/%d runs recorded, %d failed; %s, ETA %s%n", job, seen.size(),
                        pending.size(), failed, LocalRunner.duration(elapsed), seen.isEmpty() ? "?"
                                : LocalRunner.duration(elapsed / seen.size() * (pending.size() - seen.size())));
                err.flush();
                told = seen.size();
            }
            if (!queued) {
                return;
            }
            Thread.sleep(1000);
        }
    }

    private static Path bin() {
        return RobotParameterFiles.root().resolve("bin").resolve("robosim").toAbsolutePath();
    }
}
