package robosim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** summary.csv's figures, results.csv's cells, and the records' folder. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class SummaryTest {
    @TempDir
    Path dir;

    @Test
    void theIntervalIsStudentsTWithNMinusOneDegreesOfFreedom() {
        Summary.Row r = Summary.row(Map.of("team", "2"), "steps", List.of(1.0, 2.0, 3.0), 0, 1);
        assertEquals(3, r.n());
        assertEquals(2.0, r.mean(), 1e-12);
        assertEquals(1.0, r.sd(), 1e-12);
        // t(0.975, 2) = 4.302652729911275, times sd / sqrt(3)
        assertEquals(2 - 4.302652729911275 / Math.sqrt(3), r.ciLow(), 1e-9);
        assertEquals(2 + 4.302652729911275 / Math.sqrt(3), r.ciHigh(), 1e-9);
        assertEquals(1, r.failed());
        Summary.Row one = Summary.row(Map.of(), "steps", List.of(7.0), 0, 0);
        assertEquals(7.0, one.mean());
        assertTrue(Double.isNaN(one.sd()) && Double.isNaN(one.ciLow()), "one run has no spread and no interval");
    }

    private static RunRecord record(int index, String team, String status, Map<String, Object> metrics) {
        return new RunRecord("e", "f00d", index, Map.of("team", team), index % 2 + 1, index % 2 + 1, status,
                status.equals(RunRecord.OK) ? null : "robot r1's program failed: \"x\", y", metrics, List.of(), "h", 0);
    }

    private Experiment experiment() throws Exception {
        Path f = dir.resolve("e.yaml");
        Files.writeString(f, "world: {maze: {cells: 3}}\nprograms: [{class: a.B, count: '${team}'}]\n"
                + "factors: {team: [1, 2]}\nreplicates: 2\nsteps: 10\n", StandardCharsets.UTF_8);
        return ExperimentReader.read(f);
    }

    @Test
    void resultsKeepTheBuiltInMetricsFirstTheProgramsNextWallTimeLastAndQuoteWhatNeedsIt() throws Exception {
        Experiment e = experiment();
        List<RunRecord> records = new ArrayList<>();
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("wallTime", 1.5);
        m.put("explored", 12);
        m.put("steps", 40);
        m.put("endReason", "gold found by r1, at step 38");
        records.add(record(0, "1", RunRecord.OK, m));
        records.add(record(1, "1", RunRecord.FAILED, Map.of("wallTime", 0.2)));
        ResultsTable t = new ResultsTable(e, records);
        assertEquals(List.of("steps", "endReason", "explored", "wallTime"), t.metrics());
        assertEquals(List.of("steps", "explored", "wallTime"), t.numericMetrics());
        Path csv = dir.resolve("results.csv");
        t.writeResults(csv);
        assertEquals(List.of("run,replicate,seed,team,status,steps,endReason,explored,wallTime,failure",
                "0,1,1,1,ok,40,\"gold found by r1, at step 38\",12,1.5,",
                "1,2,2,1,failed,,,,0.2,\"robot r1's program failed: \"\"x\"\", y\""),
                Files.readAllLines(csv, StandardCharsets.UTF_8));
        List<Summary.Row> summary = Summary.of(e, t);
        Summary.Row steps = summary.get(0);
        assertEquals(Map.of("team", "1"), steps.factors());
        assertEquals(1, steps.n(), "the failed run gives no value");
        assertEquals(1, steps.failed());
        Path s = dir.resolve("summary.csv");
        t.writeSummary(s, summary);
        List<String> lines = Files.readAllLines(s, StandardCharsets.UTF_8);
        assertEquals("team,metric,n,missing,mean,sd,ciLow,ciHigh,failed", lines.get(0));
        assertEquals("1,steps,1,0,40,,,,1", lines.get(1));
        assertEquals("2,steps,0,0,,,,,0", lines.get(4), "a combination with no runs yet");
    }

    @Test
    void recordsAreWrittenWholeAndACollectionRefusesAnotherFilesRecords() throws Exception {
        Experiment e = experiment();
        RunRecords.write(dir, record(3, "2", RunRecord.OK, Map.of("steps", 9)));
        try (var files = Files.list(dir.resolve("runs"))) {
            assertEquals(List.of("run-000003.json"), files.map(p -> p.getFileName().toString()).toList(),
                    "no temporary file is left");
        }
        RunRecord back = RunRecords.readAll(dir).get(3);
        assertEquals(9, ((Number) back.metrics().get("steps")).intValue());
        assertEquals(Map.of("team", "2"), back.factors());
        Collector.Collected c = Collector.collect(e, "f00d", dir);
        assertEquals(List.of(0, 1, 2), c.missing());
        assertTrue(Files.readString(c.report()).contains("No record yet: 0-2"), Files.readString(c.report()));
        Path typo = dir.resolve("typo.yaml");
        Files.writeString(typo, Files.readString(dir.resolve("e.yaml")) + "metrics: [steps, stpes]\n");
        Experiment withTypo = ExperimentReader.read(typo);
        String report = Files.readString(Collector.collect(withTypo, "f00d", dir).report());
        assertTrue(report.contains("## Names no run gave\n\n`metrics` or `plot.metrics` name stpes, which no run"
                + " reported"), report);
        var x = org.junit.jupiter.api.Assertions.assertThrows(java.io.IOException.class,
                () -> Collector.collect(e, "beef", dir));
        assertTrue(x.getMessage().contains("holds runs of another experiment"), x.getMessage());
    }
}
