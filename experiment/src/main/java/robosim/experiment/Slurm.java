package robosim.experiment;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;

/**
 * A sweep on a SLURM cluster: one job array, each task running a chunk of the runs with
 * {@code robosim experiment FILE --out-dir DIR --run FIRST-LAST} on its node, into the results folder all
 * the nodes share. {@code --collect} then builds the tables, plots and report from the records.
 */
public final class Slurm {
    /** sbatch's option values the script passes through: no spaces, quotes or shell characters. */
    static final Pattern OPTION_VALUE = Pattern.compile("[A-Za-z0-9_.:+,@%=/-]{1,128}");
    /** The most tasks one array may have (SLURM's default MaxArraySize is 1001). */
    public static final int MAX_TASKS = 1000;

    /**
     * What the job asks of the cluster; null leaves the cluster's default.
     *
     * @param partition     {@code --partition}
     * @param time          {@code --time}, e.g. {@code 00:30:00}
     * @param cpusPerTask   {@code --cpus-per-task}
     * @param mem           {@code --mem}, e.g. {@code 2G}
     * @param runsPerTask   runs each task runs (in JVMs of their own, {@code cpusPerTask} at once)
     */
    public record Request(String partition, String time, Integer cpusPerTask, String mem, int runsPerTask) {
        /**
         * @throws IllegalArgumentException naming the option, the value and the rule
         */
        public Request {
            check("--partition", partition);
            check("--time", time);
            check("--mem", mem);
            if (cpusPerTask != null && cpusPerTask < 1) {
                throw new IllegalArgumentException(cpusPerTask + " was supplied for --cpus-per-task: it must be at least 1");
            }
            if (runsPerTask < 1) {
                throw new IllegalArgumentException(runsPerTask + " was supplied for --runs-per-task: it must be at least 1");
            }
        }

        private static void check(String option, String value) {
            if (value != null && !OPTION_VALUE.matcher(value).matches()) {
                throw new IllegalArgumentException("'" + value + "' was supplied for " + option + ": it is 1 to 128 letters,"
                        + " digits or . _ : + , @ % = / -");
            }
        }
    }

    private Slurm() {
    }

    /**
     * @param runs        the sweep's runs
     * @param runsPerTask runs per task
     * @return the array's tasks
     */
    public static int tasks(int runs, int runsPerTask) {
        return (runs + runsPerTask - 1) / runsPerTask;
    }

    /**
     * Writes the job script.
     *
     * @param experiment the experiment
     * @param launcher   the command that starts RoboSim's launcher on a node (this JVM's java, heap and
     *                   classpath, on the file system the nodes share), before its subcommand
     * @param out        the results folder, shared by the nodes
     * @param request    what the job asks for
     * @param runs       the runs to do, in order (a resumed sweep's are those without a record)
     * @param options    more options for each task's {@code experiment} command ({@code --classpath}, {@code --heap}, ...)
     * @return the script's path ({@code DIR/slurm/NAME.sbatch})
     * @throws IOException if it cannot be written
     * @throws IllegalArgumentException if the runs need more than {@value #MAX_TASKS} tasks
     */
    public static Path writeScript(Experiment experiment, List<String> launcher, Path out, Request request,
                                   List<Integer> runs, List<String> options) throws IOException {
        int tasks = tasks(runs.size(), request.runsPerTask());
        if (tasks > MAX_TASKS) {
            throw new IllegalArgumentException(runs.size() + " runs at " + request.runsPerTask() + " per task make " + tasks
                    + " tasks: an array has at most " + MAX_TASKS + "; give --runs-per-task "
                    + tasks(runs.size(), MAX_TASKS));
        }
        Path dir = out.resolve("slurm");
        Files.createDirectories(dir);
        Path script = dir.resolve(experiment.name() + ".sbatch");
        StringBuilder s = new StringBuilder("#!/bin/bash\n");
        s.append("#SBATCH --job-name=robosim-").append(experiment.name()).append('\n');
        s.append("#SBATCH --array=0-").append(tasks - 1).append('\n');
        s.append("#SBATCH --output=").append(dir.toAbsolutePath()).append("/task-%A_%a.out\n");
        if (request.partition() != null) {
            s.append("#SBATCH --partition=").append(request.partition()).append('\n');
        }
        if (request.time() != null) {
            s.append("#SBATCH --time=").append(request.time()).append('\n');
        }
        if (request.cpusPerTask() != null) {
            s.append("#SBATCH --cpus-per-task=").append(request.cpusPerTask()).append('\n');
        }
        if (request.mem() != null) {
            s.append("#SBATCH --mem=").append(request.mem()).append('\n');
        }
        s.append(String.format(Locale.ROOT, "# Written by robosim experiment --slurm: %d runs of %s in %d task(s),"
                + " each running%n# the runs its case below gives, each run in a JVM of its own, into %s.%n"
                + "# Submit it with: sbatch %s%n# then build the results: bin/robosim experiment %s --out-dir %s --collect%n"
                + "# ROBOSIM_JAVA, if set where you submit, names the java the nodes run instead of this one.%n",
                runs.size(), experiment.file().toAbsolutePath().normalize(), tasks,
                out.toAbsolutePath(), script.toAbsolutePath(), experiment.file().toAbsolutePath().normalize(),
                out.toAbsolutePath()));
        s.append("set -euo pipefail\n");
        // the runs are in the script, which sbatch copies when it is submitted: a later submission for
        // the same folder cannot change what this job's tasks run
        s.append("case \"$SLURM_ARRAY_TASK_ID\" in\n");
        for (int t = 0; t < tasks; t++) {
            List<Integer> chunk = runs.subList(t * request.runsPerTask(),
                    Math.min(runs.size(), (t + 1) * request.runsPerTask()));
            s.append("  ").append(t).append(") runs=").append(Report.ranges(chunk).replace(" ", "")).append(" ;;\n");
        }
        s.append("  *) echo \"task $SLURM_ARRAY_TASK_ID has no runs: the array is 0-").append(tasks - 1)
                .append("\" >&2; exit 1 ;;\nesac\n");
        s.append("exec \"${ROBOSIM_JAVA:-").append(launcher.get(0).replace("\"", "")).append("}\"");
        for (String a : launcher.subList(1, launcher.size())) {
            s.append(' ').append(quote(a));
        }
        s.append(" experiment ")
                .append(quote(experiment.file().toAbsolutePath().normalize().toString()))
                .append(" --out-dir ").append(quote(out.toAbsolutePath().toString()))
                .append(" --run \"$runs\" --parallel \"${SLURM_CPUS_PER_TASK:-1}\"");
        for (String o : options) {
            s.append(' ').append(quote(o));
        }
        s.append('\n');
        Files.writeString(script, s.toString(), StandardCharsets.UTF_8);
        try {
            Files.setPosixFilePermissions(script, PosixFilePermissions.fromString("rwxr-xr-x"));
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system: sbatch reads the script anyway
        }
        return script;
    }

    /** @return the text in single quotes for bash */
    static String quote(String s) {
        return "'" + s.replace("'", "'\\''") + "'";
    }

    /**
     * @param job a job's id
     * @return whether any of its tasks is still pending or running ({@code squeue -h -j JOB} lists it);
     *         false once it has left the queue or been forgotten
     * @throws IOException if squeue cannot be run or fails (the controller busy, say): ask again
     * @throws InterruptedException if interrupted
     */
    public static boolean queued(String job) throws IOException, InterruptedException {
        Process p = new ProcessBuilder("squeue", "-h", "-j", job, "-o", "%i").redirectErrorStream(true).start();
        // squeue's answer for one job is a few lines: it fits the pipe, so waiting first cannot block it
        if (!p.waitFor(30, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new IOException("squeue did not answer within 30 s");
        }
        String said = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        if (p.exitValue() == 0) {
            return !said.isEmpty();
        }
        if (said.contains("Invalid job id")) {
            // an ended job is forgotten after a while (MinJobAge)
            return false;
        }
        throw new IOException("squeue exited with " + p.exitValue() + ": " + said);
    }

    /**
     * Submits a script with {@code sbatch --parsable}.
     *
     * @param script the script
     * @return the job's id
     * @throws IOException if sbatch cannot be run or refuses, with what it said
     * @throws InterruptedException if interrupted while waiting
     */
    public static String submit(Path script) throws IOException, InterruptedException {
        List<String> cmd = List.of("sbatch", "--parsable", script.toAbsolutePath().toString());
        Process p;
        try {
            p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        } catch (IOException e) {
            throw new IOException("cannot run sbatch (" + e.getMessage() + "): is this a SLURM cluster's login node?"
                    + " --slurm-script writes the script without submitting it", e);
        }
        String said = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        int exit = p.waitFor();
        String id = said.lines().filter(l -> l.matches("\\d+(;.*)?")).findFirst().map(l -> l.split(";")[0]).orElse(null);
        if (id == null) {
            throw new IOException("sbatch refused " + script + " (exit " + exit + "): " + said);
        }
        if (exit != 0) {
            throw new IOException("sbatch exited with " + exit + " for job " + id + ": " + said);
        }
        return id;
    }

    /**
     * @param timeout how long to wait for an answer
     * @return whether {@code sinfo} answers here: a cluster to submit to
     */
    public static boolean available(long timeout, TimeUnit unit) {
        try {
            Process p = new ProcessBuilder("sinfo", "-h", "-o", "%P").redirectErrorStream(true).start();
            if (!p.waitFor(timeout, unit)) {
                p.destroyForcibly();
                return false;
            }
            return p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }
}
