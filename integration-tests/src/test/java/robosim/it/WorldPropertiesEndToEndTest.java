package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.scout.Scout;

/**
 * A world's properties and the run's seed reach robot programs in their welcome, whatever their API:
 * a program needs no command-line argument for what the world knows.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class WorldPropertiesEndToEndTest {
    @TempDir
    Path dir;

    @Test
    void anAriaAndAScoutProgramReadTheWorldsPropertiesAndTheRunsSeedOnceConnected() throws Exception {
        Path world = ThreadedRun.world(dir, "maze.xml", """
                <world name="maze" width="6000" height="6000" boundary="true">
                  <property name="cellSize" value="1500"/>
                  <robot name="r1" type="pioneer" x="750" y="750" th="0" params="%ROBOTS%/p3dx.p"/>
                  <robot name="s1" type="scout" x="2250" y="750" th="0" params="%ROBOTS%/scout.p"/>
                  <property name="goal" value="the gold"/>
                </world>
                """);
        try (ThreadedRun run = new ThreadedRun(world, 424_242, 0)) {
            Future<String> aria = run.robot(() -> {
                ArRobot robot = new ArRobot("r1", "127.0.0.1", run.port(), "p3dx");
                if (!robot.blockingConnect()) {
                    throw new IllegalStateException(robot.getConnectionError());
                }
                String seen = robot.getWorldProperty("cellSize", 0) + " " + robot.getWorldProperty("goal") + " "
                        + robot.getWorldProperty("absent") + " " + robot.getWorldProperties().keySet() + " "
                        + robot.getRunSeed();
                robot.sleepSimulated(100); // the run has begun: both robots are in it before either leaves
                robot.disconnect();
                return seen;
            });
            Future<String> scout = run.robot(() -> {
                Scout robot = new Scout("s1", "127.0.0.1", run.port());
                if (!robot.connect_robot()) {
                    throw new IllegalStateException(robot.getConnectionError());
                }
                String seen = robot.getWorldNumber("cellSize").getAsDouble() + " " + robot.getRunSeed();
                robot.sleepSimulated(100);
                robot.disconnect_robot();
                return seen;
            });

            assertEquals("1500.0 the gold null [cellSize, goal] 424242", aria.get(60, TimeUnit.SECONDS));
            assertEquals("1500.0 424242", scout.get(60, TimeUnit.SECONDS));
            assertEquals("every robot has disconnected", run.await().endReason());
        }
    }
}
