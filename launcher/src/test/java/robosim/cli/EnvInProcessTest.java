package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.cli.Run.execute;

import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.params.RobotParameterFiles;

/** {@code robosim env WORLD --in-process [ROBOT=]CLASS}: robot programs in the Environment's JVM. */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class EnvInProcessTest {
    private static String world(String file) {
        Path root = RobotParameterFiles.root();
        return root.resolve("testLoadFiles/environment/" + file).toString();
    }

    @Test
    void everyRobotRunsItsProgramInProcessToTheEnd() {
        Run r = execute("env", "--robot-port", "0", "--viewer-port", "0", "--no-token", "--quiet", "--steps", "300",
                "--in-process", "robosim.examples.wander.Wander", world("small-maze.xml"));
        assertEquals(0, r.exit(), r.err());
        assertTrue(r.out().contains("In-process: r1, r2"), r.out());
        assertTrue(r.out().contains("Run ended after 300 steps"), r.out());
        assertTrue(r.out().contains("robot r1: ") && r.out().contains("robot r2: "), r.out());
        assertEquals(2, r.out().lines().filter(l -> l.endsWith("ran to the end")).count(), r.out());
    }

    @Test
    void aRobotGivenByNameTakesItsOwnProgram() {
        Run r = execute("env", "--robot-port", "0", "--viewer-port", "0", "--no-token", "--quiet", "--steps", "200",
                "--in-process", "robosim.examples.scoutwander.ScoutWander", "--in-process", "r1=robosim.examples.wander.Wander",
                "--in-process", "r2=robosim.examples.wander.Wander", world("mixed-team.xml"));
        assertEquals(0, r.exit(), r.err());
        assertTrue(r.out().contains("In-process: s1, r1, r2"), r.out());
        assertEquals(3, r.out().lines().filter(l -> l.endsWith("ran to the end")).count(), r.out());
    }

    @Test
    void aProgramThatThrowsIsToldAtOnceWithItsTraceAndTheOthersGoOn() {
        Run r = execute("env", "--robot-port", "0", "--viewer-port", "0", "--no-token", "--quiet", "--connect-timeout", "2",
                "--in-process", "r1=robosim.testprograms.ThrowingProgram", "--in-process", "r2=robosim.examples.wander.Wander",
                world("small-maze.xml"));
        assertEquals(1, r.exit(), r.err());
        assertTrue(r.err().contains("robosim env: robot r1's program failed:\njava.lang.IllegalStateException: boom\n"), r.err());
        assertTrue(r.err().contains("\tat robosim.testprograms.ThrowingProgram.main(ThrowingProgram.java:"), r.err());
        assertTrue(r.err().contains("robots [r1] and 0 viewer(s) did not connect within 2 s"), r.err());
    }

    @Test
    void aClassWithoutMainIsAnOptionError() {
        Run r = execute("env", "--robot-port", "0", "--viewer-port", "0", "--no-token",
                "--in-process", "robosim.NoSuchProgram", world("small-maze.xml"));
        assertEquals(2, r.exit(), r.err());
        assertEquals("robosim env: 'robosim.NoSuchProgram' was supplied for --in-process: it is CLASS or ROBOT=CLASS,"
                + " a class with a public static main(String[]) on RoboSim's classpath or --classpath", r.firstLine());
        r.assertHintToHelp("robosim env");
    }

    @Test
    void aRobotWithoutAProgramIsAnOptionError() {
        Run r = execute("env", "--robot-port", "0", "--viewer-port", "0", "--no-token",
                "--in-process", "r1=robosim.examples.wander.Wander", world("small-maze.xml"));
        assertEquals(2, r.exit(), r.err());
        assertEquals("robosim env: robot r2 has no program: --in-process CLASS gives one to every robot,"
                + " --in-process r2=CLASS to it alone", r.firstLine());
    }
}
