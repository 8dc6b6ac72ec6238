package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.cli.Run.execute;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.experiment.Slurm;
import robosim.params.RobotParameterFiles;

/**
 * {@code robosim experiment}: a sweep run locally at several parallelisms, resumed, with a failing
 * run among good ones, and on the SLURM cluster {@code .ci/run} starts; the rows are the same
 * whichever way (the wall time apart, the machine's own figure).
 */
@Timeout(value = 240, unit = TimeUnit.SECONDS)
class ExperimentCommandTest {
    @TempDir
    Path dir;

    /** Four short runs: teams of 1 and 2 in two 3 × 3 mazes. */
    private static final String TINY = """
            name: tiny
            world:
              maze: {cells: 3}
            programs:
              - class: ${program}
                count: ${team}
            factors:
              program: [robosim.examples.goldfinder.GoldFinder]
              team: [1, 2]
            replicates: 2
            steps: 3000
            """;

    private Path file(String name, String text) throws Exception {
        Path f = dir.resolve(name);
        Files.writeString(f, text, StandardCharsets.UTF_8);
        return f;
    }

    /** @return results.csv's rows without the wall-time column */
    private static List<String> rows(Path out) throws Exception {
        List<String> lines = Files.readAllLines(out.resolve("results.csv"), StandardCharsets.UTF_8);
        List<String> header = List.of(lines.get(0).split(",", -1));
        int wall = header.indexOf("wallTime");
        assertTrue(wall > 0, lines.get(0));
        List<String> out2 = new ArrayList<>();
        for (String l : lines) {
            // no cell before the wall time holds a comma but endReason, which is quoted
            List<String> cells = new ArrayList<>(List.of(l.split(",(?=(?:[^\"]*\"[^\"]*\")*[^\"]*$)", -1)));
            cells.remove(wall);
            out2.add(String.join(",", cells));
        }
        return out2;
    }

    @Test
    void theSameRunsGiveTheSameRowsAtAnyParallelismAndAResumedSweepRunsOnlyWhatIsMissing() throws Exception {
        Path f = file("tiny.yaml", TINY);
        Run one = execute("experiment", f.toString(), "--out-dir", dir.resolve("one").toString(), "--parallel", "1");
        assertEquals(0, one.exit(), one.err());
        assertTrue(one.out().contains("Experiment tiny: 2 combination(s) x 2 replicate(s) = 4 runs; all to run"), one.out());
        assertTrue(one.err().contains("[4/4] run "), one.err());
        Run two = execute("experiment", f.toString(), "--out-dir", dir.resolve("two").toString(), "--parallel", "2",
                "--record-runs", "3");
        assertEquals(0, two.exit(), two.err());
        List<String> rows = rows(dir.resolve("one"));
        assertEquals(5, rows.size());
        assertTrue(rows.get(1).contains(",ok,") && rows.get(1).contains("gold-found"), rows.get(1));
        assertEquals(rows, rows(dir.resolve("two")), "the rows do not depend on the parallelism");
        assertTrue(Files.size(dir.resolve("two/recordings/run-000003.rsr")) > 0, "--record-runs kept run 3's recording");
        assertTrue(Files.exists(dir.resolve("two/plots/foundStep.png")));
        String report = Files.readString(dir.resolve("two/report.md"));
        assertTrue(report.contains("4 runs: 4 done, 0 failed, 0 missing") && report.contains("![foundStep](plots/foundStep.png)"),
                report);

        // a folder with records is not overwritten...
        String before = Files.readString(dir.resolve("two/runs/run-000001.json"));
        Run again = execute("experiment", f.toString(), "--out-dir", dir.resolve("two").toString());
        assertEquals(1, again.exit(), again.err());
        assertTrue(again.err().contains("already holds 4 run record(s) of this experiment: --resume goes on with them,"
                + " or give another --out-dir"), again.err());
        assertEquals(before, Files.readString(dir.resolve("two/runs/run-000001.json")), "nothing was lost");
        // ...but resumed: only the run without a record runs, and gives its row again
        Files.delete(dir.resolve("two/runs/run-000002.json"));
        Run resumed = execute("experiment", f.toString(), "--out-dir", dir.resolve("two").toString(), "--resume");
        assertEquals(0, resumed.exit(), resumed.err());
        assertTrue(resumed.out().contains("1 to run, 3 done before"), resumed.out());
        assertTrue(resumed.err().contains("[1/1] run 2 "), resumed.err());
        assertEquals(rows, rows(dir.resolve("two")));
    }

    @Test
    void aFailedRunIsRecordedWithItsReasonAndTheOthersRun() throws Exception {
        Path f = file("mixed.yaml", TINY.replace("[robosim.examples.goldfinder.GoldFinder]",
                "[robosim.examples.goldfinder.GoldFinder, robosim.NoSuchProgram]").replace("replicates: 2", "replicates: 1"));
        Run r = execute("experiment", f.toString(), "--out-dir", dir.resolve("mixed").toString(), "--parallel", "2");
        assertEquals(1, r.exit(), r.err());
        assertTrue(r.out().contains("Runs: 4 of 4 recorded, 2 failed"), r.out());
        List<String> lines = Files.readAllLines(dir.resolve("mixed/results.csv"));
        assertEquals(2, lines.stream().filter(l -> l.contains(",ok,")).count(), String.join("\n", lines));
        assertTrue(lines.get(3).contains(",failed,") && lines.get(3).contains("program robosim.NoSuchProgram is no class"
                + " with a public static main(String[])"), lines.get(3));
        assertTrue(Files.readString(dir.resolve("mixed/report.md")).contains("## Failed runs"));
    }

    @Test
    void aBadFileIsToldWithItsLineAndRunsNothing() throws Exception {
        Path f = file("bad.yaml", TINY.replace("team: [1, 2]", "team: [1, -2]"));
        Run r = execute("experiment", f.toString(), "--out-dir", dir.resolve("bad").toString());
        assertEquals(2, r.exit(), r.err());
        assertEquals("robosim experiment: " + f + " line 6: -2 is given for programs' count: it must be from 0 to 10000"
                + " in run 2 (program=robosim.examples.goldfinder.GoldFinder, team=-2)", r.firstLine());
        assertTrue(Files.notExists(dir.resolve("bad")), "nothing was made");
    }

    @Test
    void theScriptForAClusterPassesTheRequestOnAndSplitsTheRunsIntoTasks() throws Exception {
        Path f = file("tiny.yaml", TINY);
        Run r = execute("experiment", f.toString(), "--out-dir", dir.resolve("c").toString(), "--slurm-script",
                "--partition", "short", "--time", "00:20:00", "--cpus-per-task", "2", "--mem", "2G", "--runs-per-task", "3");
        assertEquals(0, r.exit(), r.err());
        Path script = dir.resolve("c/slurm/tiny.sbatch");
        String s = Files.readString(script);
        for (String line : List.of("#SBATCH --array=0-1", "#SBATCH --partition=short", "#SBATCH --time=00:20:00",
                "#SBATCH --cpus-per-task=2", "#SBATCH --mem=2G", "#SBATCH --output=" + dir.resolve("c/slurm") + "/task-%A_%a.out")) {
            assertTrue(s.contains(line + "\n"), line + " in\n" + s);
        }
        assertTrue(s.contains(" experiment '" + f + "' --out-dir '" + dir.resolve("c") + "' --run \"$runs\""), s);
        assertTrue(s.contains("  0) runs=0-2 ;;\n  1) runs=3 ;;\n"), "each task's runs are in the script: " + s);
        assertTrue(r.out().contains("Submit it with: sbatch " + script), r.out());
        Run bad = execute("experiment", f.toString(), "--slurm-script", "--partition", "a b");
        assertEquals(2, bad.exit());
        assertTrue(bad.firstLine().contains("'a b' was supplied for --partition"), bad.firstLine());
        // 2 runs at once and the launcher, 512m each: 1536M at least
        Run small = execute("experiment", f.toString(), "--slurm-script", "--cpus-per-task", "2", "--runs-per-task", "3",
                "--mem", "1G");
        assertEquals(2, small.exit());
        assertTrue(small.firstLine().contains("'1G' was supplied for --mem: each task runs its launcher and 2 run(s) at"
                + " once, each a JVM of --heap 512m, so it needs at least 1536M"), small.firstLine());
        assertEquals(0, execute("experiment", f.toString(), "--out-dir", dir.resolve("m").toString(), "--slurm-script",
                "--mem", "1536").exit(), "1536 megabytes hold the launcher and a run");
    }

    @Test
    void theShowcasesSmallVariantGivesTheSameRowsOnSlurmAsHere() throws Exception {
        boolean cluster = Slurm.available(10, TimeUnit.SECONDS);
        if (!cluster) {
            System.err.println("SKIPPED ExperimentCommandTest: no SLURM cluster answers sinfo here"
                    + " (.ci/run starts one; sudo .ci/slurm-cluster start on a developer's machine)");
        }
        Assumptions.assumeTrue(cluster, "no SLURM cluster answers sinfo here (.ci/run starts one;"
                + " sudo .ci/slurm-cluster start on a developer's machine)");
        String small = RobotParameterFiles.root().resolve("examples/experiments/goldfinder-small.yaml").toString();
        Run local = execute("experiment", small, "--out-dir", dir.resolve("local").toString(), "--parallel", "2");
        assertEquals(0, local.exit(), local.err());
        Run slurm = execute("experiment", small, "--out-dir", dir.resolve("slurm").toString(), "--slurm", "--wait");
        assertEquals(0, slurm.exit(), slurm.out() + slurm.err());
        assertTrue(slurm.out().contains("Submitted job "), slurm.out());
        assertTrue(slurm.out().contains("Runs: 8 of 8 recorded, 0 failed"), slurm.out());
        assertEquals(rows(dir.resolve("local")), rows(dir.resolve("slurm")));
    }
}
