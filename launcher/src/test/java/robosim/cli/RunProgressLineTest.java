package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import robosim.env.net.RunProgress.Phase;
import robosim.env.net.RunProgress.Status;

/**
 * What the Environment's progress looks like, driven by a clock of the test's own: on a terminal one
 * line redrawn in place that never outgrows the terminal; anywhere else plain lines, few and bounded
 * in number however long the run; and the waits that say what they wait for, for how long of how long.
 */
class RunProgressLineTest {
    private static final long S = TimeUnit.SECONDS.toNanos(1);
    private static final long TICK = TimeUnit.MILLISECONDS.toNanos(RunProgressLine.INTERVAL_MS);

    private final StringWriter text = new StringWriter();
    private long now;

    private RunProgressLine line(boolean terminal, int width) {
        return new RunProgressLine(new StatusLine(new PrintWriter(text), terminal, width), () -> now,
                TimeUnit.SECONDS.toNanos(RunProgressLine.PLAIN_EVERY_S), false);
    }

    private static Status running(long step, long maxSteps, long runNanos) {
        return new Status(Phase.RUNNING, step, step * 100, 100, maxSteps, 3, 3, List.of(), 0, 0, runNanos, 0, 0);
    }

    private static Status connecting(long waitedNanos, List<String> missing) {
        return new Status(Phase.CONNECTING, 0, 0, 100, 0, 3, 3 - missing.size(), missing, 0, 0, 0, waitedNanos,
                600 * S);
    }

    /** Feeds a run of {@code seconds} at 1000 steps a second, as the server would: every tick. */
    private void run(RunProgressLine p, long seconds, long maxSteps) {
        long start = now;
        for (long t = 0; t <= seconds * S; t += TICK) {
            now = start + t;
            p.progress(running(t / 1_000_000, maxSteps, t));
        }
    }

    private List<String> lines() {
        return text.toString().lines().toList();
    }

    @Test
    void aLongRunWithoutALimitWritesOnePlainLineEveryTenSeconds() {
        RunProgressLine p = line(false, 80);
        run(p, 3600, 0);
        p.close();
        List<String> lines = lines();
        assertTrue(lines.size() >= 350 && lines.size() <= 361, lines.size() + " lines for an hour");
        assertFalse(text.toString().contains("\r"), "no carriage returns in a log");
        Pattern plain = Pattern.compile("step \\d+, \\d+(\\.\\dk)? steps/s, [\\d.]+x real time, 3 robots, \\d+:\\d\\d(:\\d\\d)? elapsed");
        for (String l : lines) {
            assertTrue(plain.matcher(l).matches(), l);
        }
        assertEquals("step 10000, 1000 steps/s, 100x real time, 3 robots, 0:10 elapsed", lines.get(0));
    }

    @Test
    void aRunWithALimitAlsoSaysEachTenthAndTheTimeLeft() {
        RunProgressLine p = line(false, 80);
        run(p, 50, 50_000);
        List<String> lines = lines();
        // a tenth every 5 s, and no more: the 10 s lines fall on tenths
        assertEquals(10, lines.size(), String.join("\n", lines));
        assertEquals("step 5000 of 50000 (10%), 1000 steps/s, 100x real time, 3 robots, 0:05 elapsed, ETA 0:45",
                lines.get(0));
        assertTrue(lines.get(9).startsWith("step 50000 of 50000 (100%)"), lines.get(9));
    }

    @Test
    void aShortFastRunWithALimitWritesAtMostOneLineASecond() {
        RunProgressLine p = line(false, 80);
        run(p, 3, 3_000);
        assertTrue(lines().size() <= 4, String.join("\n", lines()));
    }

    @Test
    void onATerminalTheLineIsRedrawnInPlaceAndClearedAtTheEnd() {
        RunProgressLine p = line(true, 100);
        run(p, 5, 5_000);
        p.close();
        String all = text.toString();
        assertFalse(all.contains("\n"), "one line, redrawn: " + all);
        assertTrue(all.split("\r").length > 10, "redrawn a few times a second");
        assertTrue(all.contains("\r[#####-----]  50% step 2500/5000  1000/s  100x real time  3 robots  ETA 0:02"), all);
        assertTrue(Pattern.compile("\r +\r$").matcher(all).find(), "cleared at the end: " + all);
    }

    @Test
    void onANarrowTerminalTheLineIsCutToFitSoThatItNeverWraps() {
        RunProgressLine p = line(true, 40);
        run(p, 5, 5_000);
        for (String frame : text.toString().split("\r")) {
            assertTrue(frame.length() <= 39, "fits in 40 columns: '" + frame + "'");
        }
        assertTrue(text.toString().contains("~"), "cut lines end in ~");
    }

    @Test
    void waitingForRobotsSaysWhichHowLongAndOfHowLongEveryFewSeconds() {
        RunProgressLine p = line(false, 80);
        for (long t = 0; t <= 30 * S; t += TICK) {
            now = t;
            p.progress(connecting(t, t < 20 * S ? List.of("r2", "r3") : List.of("r3")));
        }
        assertEquals(List.of(
                "waiting for robots r2, r3 (1 of 3 connected) - 2 s of 600",
                "waiting for robots r2, r3 (1 of 3 connected) - 7 s of 600",
                "waiting for robots r2, r3 (1 of 3 connected) - 12 s of 600",
                "waiting for robots r2, r3 (1 of 3 connected) - 17 s of 600",
                "waiting for robot r3 (2 of 3 connected) - 22 s of 600",
                "waiting for robot r3 (2 of 3 connected) - 27 s of 600"), lines());
    }

    @Test
    void aLongWaitWritesALineEveryHalfMinuteAfterTheFirstMinute() {
        RunProgressLine p = line(false, 80);
        for (long t = 0; t <= 600 * S; t += TICK) {
            now = t;
            p.progress(connecting(t, List.of("r3")));
        }
        // 2, 7, ..., 57 s, then 62, 92, ... 572 s
        assertEquals(12 + 18, lines().size(), String.join("\n", lines()));
    }

    @Test
    void aStepHeldUpSaysWhoseRequestsItWaitsForOnceItHasWaitedASecond() {
        RunProgressLine p = line(false, 80);
        Status brief = new Status(Phase.STEP_HELD, 41, 4100, 100, 0, 3, 3, List.of("r3"), 0, 0, 5 * S, S / 2, 10 * S);
        p.progress(brief);
        assertEquals(List.of(), lines(), "a step held half a second is running");
        for (long t = S; t <= 4 * S; t += TICK) {
            p.progress(new Status(Phase.STEP_HELD, 41, 4100, 100, 0, 3, 3, List.of("r3"), 0, 0, 5 * S + t, t, 10 * S));
        }
        assertEquals(List.of("step 42 waits for robot r3's requests - 2 s of 10"), lines());
    }

    @Test
    void viewersWaitedForAreNamedAndLongListsOfRobotsAreCut() {
        assertEquals("waiting for 1 viewer - 3 s of 60", RunProgressLine.describeWait(new Status(Phase.CONNECTING, 0, 0,
                100, 0, 2, 2, List.of(), 0, 1, 0, 3 * S, 60 * S)));
        assertEquals("waiting for robots r1, r2, r3, r4, r5, r6 and 2 more (0 of 8 connected) and 2 viewers - 0 s of 1.5",
                RunProgressLine.describeWait(new Status(Phase.CONNECTING, 0, 0, 100, 0, 8, 0,
                        List.of("r1", "r2", "r3", "r4", "r5", "r6", "r7", "r8"), 0, 2, 0, 0, 1500_000_000L)));
    }

    @Test
    void aWaitWithNoTimeLimitSaysSoInsteadOfALimitOfNought() {
        assertEquals("waiting for robot r2 (1 of 2 connected) - 4 s, no time limit",
                RunProgressLine.describeWait(new Status(Phase.CONNECTING, 0, 0, 100, 0, 2, 1, List.of("r2"), 0, 0, 0,
                        4 * S, 0)));
    }

    @Test
    void refusedRobotsAreNamedWithWhyAndAWaitWhoseRobotsWereAllRefusedSaysWhatToDo() {
        Map<String, String> one = new LinkedHashMap<>();
        one.put("r1", "presented no run secret");
        assertEquals("waiting for robots r1, r2 (0 of 2 connected) - 3 s of 600; refused: r1 (presented no run secret)",
                RunProgressLine.describeWait(new Status(Phase.CONNECTING, 0, 0, 100, 0, 2, 0, List.of("r1", "r2"), 0, 0,
                        0, 3 * S, 600 * S, one)));
        Map<String, String> both = new LinkedHashMap<>(one);
        both.put("r2", "presented a wrong run secret");
        String all = RunProgressLine.describeWait(new Status(Phase.CONNECTING, 0, 0, 100, 0, 2, 0, List.of("r1", "r2"),
                0, 0, 0, 3 * S, 600 * S, both));
        assertTrue(all.startsWith("waiting for robots r1, r2 (0 of 2 connected) - 3 s of 600; refused: r1 (presented no"
                + " run secret), r2 (presented a wrong run secret). Every robot waited for was refused: start them on this"
                + " machine as the same user"), all);
        Map<String, String> name = Map.of("r9", "world empty-room has no robot named 'r9'");
        assertTrue(RunProgressLine.describeWait(new Status(Phase.CONNECTING, 0, 0, 100, 0, 1, 0, List.of("r9"), 0, 0, 0,
                S, 600 * S, name)).endsWith("Every robot waited for was refused: fix what the refusals say and start"
                + " them again; the Environment keeps waiting"));
    }

    @Test
    void aNewRefusalIsShownAtOnceOffATerminal() {
        RunProgressLine p = line(false, 200);
        now = 0;
        p.progress(new Status(Phase.CONNECTING, 0, 0, 100, 0, 2, 0, List.of("r1", "r2"), 0, 0, 0, S / 2, 600 * S));
        assertEquals(List.of(), lines(), "no line before the schedule's first");
        p.progress(new Status(Phase.CONNECTING, 0, 0, 100, 0, 2, 0, List.of("r1", "r2"), 0, 0, 0, S / 2 + TICK,
                600 * S, Map.of("r2", "presented no run secret")));
        assertEquals(List.of("waiting for robots r1, r2 (0 of 2 connected) - 0 s of 600; refused: r2 (presented no"
                + " run secret)"), lines());
    }

    @Test
    void durationsAreMinutesAndSecondsOrHours() {
        assertEquals("0:07", RunProgressLine.duration(7 * S));
        assertEquals("12:05", RunProgressLine.duration(725 * S));
        assertEquals("2:00:01", RunProgressLine.duration(7201 * S));
    }
}
