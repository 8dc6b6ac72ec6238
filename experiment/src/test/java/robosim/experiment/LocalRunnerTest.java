package robosim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** The local sweep's bookkeeping: a worker that dies without its record, and one that writes it. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class LocalRunnerTest {
    @TempDir
    Path dir;

    @Test
    void aWorkerThatDiesWithoutItsRecordLeavesAFailedRecordWithItsLogsEndAndTheOthersRun() throws Exception {
        Path f = dir.resolve("e.yaml");
        Files.writeString(f, "world: {maze: {cells: 3}}\nprograms: [{class: a.B, count: 1}]\nreplicates: 3\n"
                + "steps: 10\n", StandardCharsets.UTF_8);
        Experiment e = ExperimentReader.read(f);
        RunExecutor executor = new RunExecutor(e, "f00d", dir, getClass().getClassLoader(), null);
        // run 1's worker dies; the others stand in for a worker that writes its record (a copy of one)
        RunRecords.write(dir.resolve("stand-in"), executor.lost(e.run(0), "a stand-in record"));
        Path record = RunRecords.file(dir.resolve("stand-in"), 0);
        StringWriter said = new StringWriter();
        LocalRunner runner = new LocalRunner(e, executor, dir, run -> run == 1
                ? List.of("sh", "-c", "echo out of memory, say; exit 3")
                : List.of("sh", "-c", "sed 's/\"index\" : 0/\"index\" : " + run + "/' " + record + " > "
                + RunRecords.file(dir, run)), 2, new PrintWriter(said));
        Files.createDirectories(dir.resolve("runs"));
        assertEquals(3, runner.run(List.of(0, 1, 2)), said.toString());
        RunRecord lost = RunRecords.read(dir, 1);
        assertEquals(RunRecord.FAILED, lost.status());
        assertTrue(lost.failure().startsWith("the run's JVM exited with code 3 and wrote no record;"), lost.failure());
        assertTrue(lost.failure().endsWith("out of memory, say"), lost.failure());
        assertEquals("a stand-in record", RunRecords.read(dir, 2).failure(), "the other runs went on");
        assertTrue(said.toString().contains("[3/3] run "), said.toString());
        assertEquals(3, runner.timings().size());
        assertEquals(3, Files.readAllLines(LocalRunner.timingFile(dir)).size());
    }
}
