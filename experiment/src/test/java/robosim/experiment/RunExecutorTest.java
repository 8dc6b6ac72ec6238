package robosim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** A run in this JVM: GoldFinder in a small maze, over the in-process link. */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class RunExecutorTest {
    @TempDir
    Path dir;

    private Experiment experiment(String programs) throws Exception {
        Path f = dir.resolve("e.yaml");
        Files.writeString(f, "world: {maze: {cells: 3}}\nprograms:\n" + programs
                + "factors: {team: [1, 2]}\nsteps: 5000\n", StandardCharsets.UTF_8);
        return ExperimentReader.read(f);
    }

    private static Map<String, Object> simulated(RunRecord r) {
        Map<String, Object> m = new LinkedHashMap<>(r.metrics());
        m.remove(Metrics.WALL_TIME);
        return m;
    }

    @Test
    void aRunFindsTheGoldAndGivesTheSameMetricsEachTime() throws Exception {
        Experiment e = experiment("  - {class: robosim.examples.goldfinder.GoldFinder, count: '${team}'}\n");
        RunExecutor x = new RunExecutor(e, "f", dir, getClass().getClassLoader(), null);
        RunRecord first = x.execute(e.run(1), dir.resolve("rec/run-1.rsr"));
        assertTrue(first.ok(), first.failure());
        assertEquals("gold-found", first.metrics().get(Metrics.ENDING));
        assertEquals(1, first.metrics().get(Metrics.FOUND));
        long found = ((Number) first.metrics().get(Metrics.FOUND_STEP)).longValue();
        long bound = ((Number) first.metrics().get(Metrics.LOWER_BOUND)).longValue();
        assertTrue(bound > 0 && found >= bound, "found at " + found + ", no sooner than the bound " + bound);
        assertEquals(2, first.robots().size());
        // GoldFinder reports the cells each robot sensed; the run's value is the robots' mean
        double sensed = (Double) first.metrics().get("cellsSensed");
        assertTrue(sensed >= 1 && sensed <= 9, "cells sensed in a 3 x 3 maze: " + sensed);
        assertTrue(Files.size(dir.resolve("rec/run-1.rsr")) > 0, "the recording was kept");
        RunRecord again = x.execute(e.run(1), null);
        assertEquals(simulated(first), simulated(again), "the same run gives the same row");
    }

    @Test
    void theProgramsMetricsAreMadeOneAsTheFileSaysAndAProgramMayEndTheRun() throws Exception {
        Path f = dir.resolve("r.yaml");
        Files.writeString(f, "world: {maze: {cells: 3}}\nprograms: [{class: " + Reporter.class.getName()
                + ", count: 2}]\naggregate: {looks: sum}\nsteps: 5000\n", StandardCharsets.UTF_8);
        Experiment e = ExperimentReader.read(f);
        RunRecord r = new RunExecutor(e, "f", dir, getClass().getClassLoader(), null).execute(e.run(0), null);
        assertTrue(r.ok(), r.failure());
        assertEquals("robot-ended", r.metrics().get(Metrics.ENDING));
        assertTrue(((String) r.metrics().get(Metrics.END_REASON)).startsWith("ended by robot r1 at step "),
                (String) r.metrics().get(Metrics.END_REASON));
        assertTrue(((String) r.metrics().get(Metrics.END_REASON)).endsWith(": looked 10 times"));
        // r1 reported 10 and ended the run before r2 reached 20: the sum is 10 and r2's last count
        double looks = (Double) r.metrics().get("looks");
        double r2 = ((Number) r.robots().get(1).figures().get("looks")).doubleValue();
        assertEquals(10 + r2, looks, 1e-9);
        assertEquals(10.0, ((Number) r.robots().get(0).figures().get("looks")).doubleValue());
        assertTrue(r2 >= 10 && r2 < 20, "r2 had looked " + r2 + " times when the run ended");
        assertEquals(0L, ((Number) r.metrics().get(Metrics.MESSAGES_SENT)).longValue());
    }

    @Test
    void aProgramThatIsNoProgramFailsItsRunWithTheReason() throws Exception {
        Experiment e = experiment("  - {class: robosim.NoSuchProgram, count: 1}\n");
        RunRecord r = new RunExecutor(e, "f", dir, getClass().getClassLoader(), null).execute(e.run(0), null);
        assertEquals(RunRecord.FAILED, r.status());
        assertTrue(r.failure().contains("program robosim.NoSuchProgram is no class with a public static main"),
                r.failure());
        assertNull(r.metrics().get(Metrics.STEPS));
    }

    @Test
    void aProgramThatThrowsFailsItsRunAndTheRunStillEnds() throws Exception {
        Experiment e = experiment("  - {class: " + Thrower.class.getName() + ", count: 1}\n");
        RunRecord r = new RunExecutor(e, "f", dir, getClass().getClassLoader(), null).execute(e.run(0), null);
        assertEquals(RunRecord.FAILED, r.status());
        assertTrue(r.failure().startsWith("robot r1's program failed: java.lang.IllegalStateException: no robot today"),
                r.failure());
    }

    @Test
    void aRobotJvmThatFailsFailsItsRunAsAThreadWould() throws Exception {
        Experiment e = experiment("  - {class: robosim.examples.goldfinder.GoldFinder, count: 1, link: jvm}\n");
        // a stand-in for robosim robot: a JVM that says why it fails and exits with 1 at once
        RobotJvms failing = (cls, robot, port, secret, log, args) -> new ProcessBuilder("sh", "-c",
                "echo robot " + robot + " could not load its program; exit 1").redirectErrorStream(true)
                .redirectOutput(log.toFile()).start();
        RunRecord r = new RunExecutor(e, "f", dir, getClass().getClassLoader(), failing).execute(e.run(0), null);
        assertEquals(RunRecord.FAILED, r.status());
        assertTrue(r.failure().startsWith("robot r1's JVM exited with code 1; the end of its log ("), r.failure());
        // stopped at once, not after the 60 s the Environment waits for a robot to connect
        assertTrue(r.failure().contains("robot r1 could not load its program; the run was stopped"), r.failure());
    }

    /** A program that fails before its robot connects. */
    public static final class Thrower {
        private Thrower() {
        }

        /** @param args robot, host, port */
        public static void main(String[] args) {
            throw new IllegalStateException("no robot today");
        }
    }
}
