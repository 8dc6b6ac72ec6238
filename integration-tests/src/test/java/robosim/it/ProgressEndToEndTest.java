package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.examples.wander.Wander;

/**
 * What the command line says while it runs, each command in a JVM of its own whose output is no
 * terminal: {@code robosim env}'s progress as plain lines, few and bounded in number; a robot that
 * waits for its first step says so; a robot program that throws mid-run shows its stack trace, and
 * {@code robosim robot} exits 1.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class ProgressEndToEndTest {
    private static final String WANDER = "robosim.examples.wander.Wander";
    private static final Pattern LISTENING = Pattern.compile("robots on 127\\.0\\.0\\.1:(\\d+), viewers on");

    @TempDir
    Path dir;

    /** Wander robots on daemon threads of this JVM, one per name. */
    private static List<Thread> wanderers(int port, String... names) {
        List<Thread> robots = new ArrayList<>();
        for (String name : names) {
            Thread t = new Thread(() -> {
                ArRobot robot = new ArRobot(name, "127.0.0.1", port, "p3dx");
                if (robot.blockingConnect()) {
                    robot.enableMotors();
                    new Wander(robot).run();
                }
            }, "wander-" + name);
            t.setDaemon(true);
            t.start();
            robots.add(t);
        }
        return robots;
    }

    @Test
    void envShowsItsProgressAsAFewPlainLinesWhenItsOutputIsNoTerminal() throws Exception {
        String world = LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml").toString();
        try (LauncherJvm env = new LauncherJvm("env", world, "--port", "0", "--viewer-port", "0", "--no-token",
                "--realtime", "--steps", "40")) {
            Matcher m = LISTENING.matcher(env.awaitLine(l -> LISTENING.matcher(l).find(), 60));
            assertTrue(m.find());
            wanderers(Integer.parseInt(m.group(1)), "r1", "r2");
            assertEquals(0, env.awaitExit(60), env.output());
            List<String> progress = env.lines().stream().filter(l -> l.startsWith("step ")).toList();
            // 40 steps of 100 ms: a line at each tenth, at most one a second
            assertTrue(progress.size() >= 2 && progress.size() <= 6, env.output());
            Pattern plain = Pattern.compile("step \\d+ of 40 \\(\\d+%\\), \\d+ steps/s, [\\d.]+x real time, 2 robots, "
                    + "0:0\\d elapsed, ETA 0:0\\d");
            for (String l : progress) {
                assertTrue(plain.matcher(l).matches(), l);
            }
            assertFalse(env.lines().stream().anyMatch(l -> l.startsWith("[")), "no terminal bar:\n" + env.output());
            assertTrue(env.lines().contains("Run ended after 40 steps (4.0 s simulated): step limit 40 reached"),
                    env.output());
        }
    }

    @Test
    void aRobotWaitingForTheOthersSaysItWaitsForStep1() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback().withMaxSteps(5));
             LauncherJvm robot = new LauncherJvm("robot", WANDER, "r1", "127.0.0.1", Integer.toString(h.robotPort()))) {
            String waiting = robot.awaitLine(l -> l.contains("waiting for step 1"), 60);
            assertTrue(Pattern.matches("robosim robot: robot r1 is connected to the Environment at 127\\.0\\.0\\.1:"
                    + h.robotPort() + ", waiting for step 1: the run starts once every robot of the world has connected"
                    + " - \\d+ s", waiting), waiting);
            wanderers(h.robotPort(), "r2");
            assertEquals("step limit 5 reached", h.await().endReason());
            assertEquals(0, robot.awaitExit(30), robot.output());
        }
    }

    @Test
    void aRobotWaitingQuietlySaysNothingUntilTheRunEnds() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback().withMaxSteps(5));
             LauncherJvm robot = new LauncherJvm("robot", "--quiet", WANDER, "r1", "127.0.0.1",
                     Integer.toString(h.robotPort()))) {
            // left waiting for longer than the first two waiting lines would take: a wait for
            // something NOT to happen, which no condition marks, so a fixed time is the point
            Thread.sleep(TimeUnit.SECONDS.toMillis(8));
            wanderers(h.robotPort(), "r2");
            assertEquals("step limit 5 reached", h.await().endReason());
            assertEquals(0, robot.awaitExit(30), robot.output());
            assertFalse(robot.output().contains("waiting"), robot.output());
        }
    }

    @Test
    void aRobotProgramThatThrowsMidRunShowsItsStackTraceAndExits1() throws Exception {
        Path p3dx = LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p").toAbsolutePath();
        Path world = dir.resolve("one-robot.xml");
        Files.writeString(world, """
                <?xml version="1.0" encoding="UTF-8"?>
                <world name="one-robot" width="6000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="1500" y="1500" th="45" params="%s"/>
                </world>
                """.formatted(p3dx));
        try (LocalEnvironment h = new LocalEnvironment(WorldReader.read(world), 1,
                ServerOptions.loopback().withMaxSteps(500));
             LauncherJvm robot = new LauncherJvm("robot", FailingDriver.class.getName(), "r1", "127.0.0.1",
                     Integer.toString(h.robotPort()))) {
            RunReport report = h.await();
            assertEquals("every robot has disconnected", report.endReason());
            assertEquals(1, robot.awaitExit(30), robot.output());
            String out = robot.output();
            assertTrue(out.contains("robosim robot: robot r1's program failed:\njava.lang.IllegalStateException: no wall within "),
                    out);
            assertTrue(Pattern.compile("\n\tat robosim\\.it\\.FailingDriver\\.turnAtTheWall\\(FailingDriver\\.java:\\d+\\)\n"
                    + "\tat robosim\\.it\\.FailingDriver\\.main\\(FailingDriver\\.java:\\d+\\)\n").matcher(out + "\n").find(),
                    "the program's frames with file and line:\n" + out);
            assertFalse(out.contains("RobotProgram") || out.contains("reflect."), "none of the launcher's:\n" + out);
            assertTrue(out.contains("robot r1 left the run at 127.0.0.1:" + h.robotPort()), out);
        }
    }
}
