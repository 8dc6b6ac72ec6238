package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.env.core.RobotSummary;
import robosim.env.net.Departure;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.examples.teleop.Teleop;

/** The keyboard teleop ({@code examples/teleop}) driven by commands piped in, as from a file: in a thread, and by {@code bin/robosim robot}. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class TeleopExampleTest {
    @TempDir
    Path dir;

    @Test
    void binRobosimRobotRunsTheTeleopOnCommandsPipedIntoItsStandardInput() throws Exception {
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(room()), 1, ServerOptions.loopback());
             LauncherJvm teleop = new LauncherJvm("robot", Teleop.class.getName(), "r1", "127.0.0.1",
                     String.valueOf(env.robotPort()))) {
            teleop.input("w\nw\nwait 20\nq\n");
            assertEquals(0, teleop.awaitExit(90), teleop.output());
            RunReport report = env.await(30);
            assertEquals(Departure.Kind.LEFT, report.departure("r1").orElseThrow().kind());
            assertTrue(report.robots().get(0).x() > 1700, "drove forward: " + report.robots().get(0).x());
            assertTrue(teleop.output().contains("vel 200 mm/s, rotVel 0 deg/s"), teleop.output());
            assertTrue(teleop.output().contains("robot r1 left the run"), teleop.output());
        }
    }

    private Path room() throws Exception {
        return ThreadedRun.world(dir, "room.xml", """
                <?xml version="1.0" encoding="UTF-8"?>
                <world name="room" width="6000" height="6000" stepMs="100" boundary="true">
                  <robot name="r1" type="pioneer" x="1500" y="3000" th="0" params="%ROBOTS%/p3dx.p"/>
                </world>
                """);
    }

    @Test
    void pipedCommandsDriveForwardTurnRightStopAndQuitAndABadLineIsNamed() throws Exception {
        Path world = room();
        String commands = "w\nw\nwait 30\nd\nd\nd\nwait 30\njump\nwait 0\nx\nwait 10\nq\nw\nwait 50\n";
        try (ThreadedRun run = new ThreadedRun(world, 1, 600)) {
            Future<String> teleop = run.robot(() -> {
                ArRobot robot = new ArRobot("r1", "127.0.0.1", run.port(), "p3dx");
                assertTrue(robot.blockingConnect(), robot.getConnectionError());
                robot.enableMotors();
                ByteArrayOutputStream out = new ByteArrayOutputStream();
                new Teleop(robot, new PrintStream(out, true, StandardCharsets.UTF_8))
                        .run(new BufferedReader(new StringReader(commands)));
                robot.disconnect();
                return out.toString(StandardCharsets.UTF_8);
            });
            String out = teleop.get(90, TimeUnit.SECONDS);
            RunReport report = run.await();
            assertTrue(report.steps() < 150, "q ends it; the commands after it are not read: " + report.steps());
            RobotSummary r1 = report.robots().get(0);
            assertEquals(Departure.Kind.LEFT, report.departure("r1").orElseThrow().kind());
            assertTrue(r1.x() > 2300, "drove forward (east): " + r1.x());
            assertTrue(r1.y() < 2950, "turned right (south): " + r1.y());
            assertTrue(r1.th() < -30, "heading turned right: " + r1.th());
            assertEquals(0, r1.collisions());
            assertTrue(out.contains("teleop: 'jump' is not a command: " + Teleop.COMMANDS), out);
            assertTrue(out.contains("teleop: 'wait 0' is not a command: "), out);
            assertTrue(out.contains("vel 200 mm/s, rotVel -30 deg/s"), out);
            assertTrue(out.contains("vel 0 mm/s, rotVel 0 deg/s"), out);
        }
    }
}
