package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.cli.Background;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.examples.gotoaction.GotoActionExample;

/** ARIA's gotoActionExample, shipped as {@code examples/goto-action}: the robot drives its square corner by corner. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class GotoActionExampleTest {
    @TempDir
    Path dir;

    /** What the program printed and how many goals it achieved. */
    private record Seen(String out, int achieved) { }

    @Test
    void theRobotReachesTheCornersOfItsSquareInTurnAndStopsWhenItsTimeIsUp() throws Exception {
        Path world = dir.resolve("room.xml");
        Files.writeString(world, """
                <world name="room" width="8000" height="8000" boundary="true">
                  <robot name="r1" type="pioneer" x="1000" y="1000" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.xml")));
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 7, ServerOptions.loopback())) {
            CompletableFuture<Seen> seen = Background.supply("robot r1", () -> {
                ArRobot robot = ActionPrograms.connect(env, "r1");
                ByteArrayOutputStream bytes = new ByteArrayOutputStream();
                int achieved = GotoActionExample.drive(robot, 2500, 40_000,
                        new PrintStream(bytes, true, StandardCharsets.UTF_8));
                robot.disconnect();
                return new Seen(bytes.toString(StandardCharsets.UTF_8), achieved);
            });
            Seen s = seen.get(90, TimeUnit.SECONDS);
            RunReport report = env.await(60);
            RobotSummary r = report.robots().get(0);

            assertTrue(s.achieved() >= 2, s.achieved() + " goals in 40 s:\n" + s.out());
            assertTrue(s.out().contains("Going to next goal at 3500 1000"), s.out());
            assertTrue(s.out().contains("Going to next goal at 3500 3500"), s.out());
            assertTrue(s.out().contains("40 seconds have elapsed"), s.out());
            assertEquals(0, r.collisions());
            assertTrue(r.distance() > 2 * 2500 - 200, "it drove at least two sides: " + r.distance());
        }
    }
}
