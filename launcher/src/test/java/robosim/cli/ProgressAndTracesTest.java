package robosim.cli;

import static robosim.cli.Run.execute;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.hw.RunEndWatch;

/**
 * What the launcher says while it waits, and when a robot program fails: executed in this JVM with
 * captured writers, which are no terminal, so progress comes as plain lines.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class ProgressAndTracesTest {


    private static String emptyRoom() {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (!p.resolve("testLoadFiles").toFile().isDirectory()) {
            p = p.getParent();
        }
        return p.resolve("testLoadFiles/environment/empty-room.xml").toString();
    }

    @Test
    void anEnvironmentWaitingForRobotsThatNeverComeSaysForWhichAndHowLongOfHowLong() {
        Run r = execute("env", emptyRoom(), "--robot-port", "0", "--viewer-port", "0", "--no-token", "--connect-timeout", "3");
        assertEquals(1, r.exit(), r.err());
        List<String> waiting = r.err().lines().filter(l -> l.startsWith("waiting for")).toList();
        assertEquals(List.of("waiting for robots r1, r2 (0 of 2 connected) - 2 s of 3"), waiting, r.err());
        assertTrue(r.err().contains("robosim env: robots [r1, r2] and 0 viewer(s) did not connect within 3 s"),
                r.err());
        assertFalse(r.err().contains("\r"), "plain lines: " + r.err());
    }

    @Test
    void quietSaysNothingWhileWaiting() {
        Run r = execute("env", emptyRoom(), "--robot-port", "0", "--viewer-port", "0", "--no-token", "--connect-timeout", "3",
                "--quiet");
        assertEquals(1, r.exit(), r.err());
        assertFalse(r.err().contains("waiting for"), r.err());
        assertTrue(r.err().contains("did not connect within 3 s"), r.err());
    }

    @Test
    void aProgramThatThrowsShowsItsStackTraceWithItsOwnFramesAndCausesAndExits1() {
        Run r = execute("robot", "robosim.testprograms.ThrowingProgram", "r1", "127.0.0.1", "5000");
        assertEquals(1, r.exit(), r.err());
        String err = r.err();
        assertTrue(err.startsWith("robosim robot: robot r1's program failed:\n"
                + "java.lang.IllegalStateException: boom\n"), err);
        assertTrue(Pattern.compile("\tat robosim\\.testprograms\\.ThrowingProgram\\.drive\\(ThrowingProgram\\.java:\\d+\\)\n"
                + "\tat robosim\\.testprograms\\.ThrowingProgram\\.main\\(ThrowingProgram\\.java:\\d+\\)\n").matcher(err).find(),
                "the program's frames, with file and line:\n" + err);
        assertTrue(err.contains("Caused by: java.io.IOException: no map for robot r1\n"
                + "\tat robosim.testprograms.ThrowingProgram.readMap(ThrowingProgram.java:"), "the cause too:\n" + err);
        assertFalse(err.contains("RobotProgram") || err.contains("reflect") || err.contains("java.lang.Thread.run"),
                "without the launcher's frames:\n" + err);
    }

    @Test
    void aProgramWhoseClassFailsToInitializeShowsWhereAndExits1() {
        Run r = execute("robot", "robosim.testprograms.FailingInitProgram", "r1", "127.0.0.1", "5000");
        assertEquals(1, r.exit(), r.err());
        assertTrue(r.err().startsWith("robosim robot: robot r1's program failed as its class "
                + "robosim.testprograms.FailingInitProgram was initialized:\n"
                + "java.lang.NumberFormatException: For input string: \"fast\"\n"), r.err());
        assertTrue(r.err().contains("\tat robosim.testprograms.FailingInitProgram.<clinit>(FailingInitProgram.java:"),
                r.err());
        assertFalse(r.err().contains("picocli") || r.err().contains("RobotCommand"), r.err());
    }

    @Test
    void robotsWaitingForTheEnvironmentAreSaidInOneLineHoweverManyThereAre() {
        List<RunEndWatch.BeforeFirstStep> eight = new ArrayList<>();
        for (int k = 8; k >= 1; k--) {
            eight.add(new RunEndWatch.BeforeFirstStep("r" + k, "localhost:5000", true, TimeUnit.SECONDS.toNanos(k)));
        }
        assertEquals("robosim robot: robots r1, r2, r3, r4, r5, r6 and 2 more are connected to the Environment at"
                + " localhost:5000, waiting for step 1: the run starts once every robot of the world has connected - 8 s",
                RobotProgram.describe(eight, TimeUnit.SECONDS.toNanos(8)));
        assertEquals("robosim robot: robot r1 is waiting for the Environment at localhost:5000 to answer"
                + " (it keeps trying while nothing listens there) - 2 s", RobotProgram.describe(List.of(
                        new RunEndWatch.BeforeFirstStep("r1", "localhost:5000", false, TimeUnit.SECONDS.toNanos(2))),
                TimeUnit.SECONDS.toNanos(2)));
        // a robot that joined a run under way does not wait for step 1 nor for the others
        assertEquals("robosim robot: robot r9 is in the run at localhost:5000 since step 120, waiting for the next step"
                + " (the run may be paused) - 3 s", RobotProgram.describe(List.of(new RunEndWatch.BeforeFirstStep("r9",
                "localhost:5000", true, TimeUnit.SECONDS.toNanos(3), 120)), TimeUnit.SECONDS.toNanos(3)));
    }
}
