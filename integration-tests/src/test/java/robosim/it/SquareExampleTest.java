package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.aria.ArPose;
import robosim.aria.ArRobot;
import robosim.env.core.RobotSummary;
import robosim.env.net.Departure;
import robosim.env.net.RunReport;
import robosim.examples.square.Square;

/** The README's first program, shipped as {@code examples/square}: both robots of the empty room drive their squares. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class SquareExampleTest {
    @Test
    void bothRobotsDriveA1mSquareBackToWhereTheyStartedAndLeave() throws Exception {
        try (ThreadedRun run = new ThreadedRun(LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml"), 1, 600)) {
            Future<String> r1 = run.robot(() -> square("r1", run.port()));
            Future<String> r2 = run.robot(() -> square("r2", run.port()));
            String out1 = r1.get(90, TimeUnit.SECONDS);
            String out2 = r2.get(90, TimeUnit.SECONDS);
            RunReport report = run.await();
            assertEquals("every robot has disconnected", report.endReason());
            assertTrue(report.steps() < 400, "a square takes a few hundred steps: " + report.steps());
            for (RobotSummary r : report.robots()) {
                assertEquals(4 * Square.SIDE, r.distance(), 100, r.name() + " drove four sides");
                assertEquals(0, r.collisions(), r.name());
                assertEquals(Departure.Kind.LEFT, report.departure(r.name()).orElseThrow().kind(), r.name());
            }
            RobotSummary first = report.robots().get(0);
            assertEquals(1500, first.x(), 150, "r1 back where it started");
            assertEquals(1500, first.y(), 150, "r1 back where it started");
            for (String out : List.of(out1, out2)) {
                assertEquals(4, out.lines().filter(l -> l.startsWith("pose ") && l.contains("front sonar")).count(), out);
            }
        }
    }

    private static String square(String name, int port) {
        ArRobot robot = new ArRobot(name, "127.0.0.1", port, "p3dx");
        assertTrue(robot.blockingConnect(), robot.getConnectionError());
        robot.enableMotors();
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ArPose[] corners = Square.drive(robot, new PrintStream(bytes, true, StandardCharsets.UTF_8));
        robot.disconnect();
        assertEquals(4, corners.length);
        return bytes.toString(StandardCharsets.UTF_8);
    }
}
