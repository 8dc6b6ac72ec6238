package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.cli.Background;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;

/**
 * ARIA's connection callbacks on a live Environment: connect when welcomed; disconnect normally and
 * run exit when the run ends; disconnect on error when the Environment drops the robot.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class ArRobotCallbacksEndToEndTest {
    @TempDir
    Path dir;

    private Path room() throws Exception {
        Path world = dir.resolve("room.xml");
        Files.writeString(world, """
                <world name="room" width="8000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="1000" y="3000" th="0" params="%s"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.xml")));
        return world;
    }

    private static void listen(ArRobot robot, List<String> calls) {
        robot.addStabilizingCB(() -> calls.add("stabilizing"));
        robot.addConnectCB(() -> calls.add("connect " + robot.isConnected()));
        robot.addDisconnectNormallyCB(() -> calls.add("normally"));
        robot.addDisconnectOnErrorCB(() -> calls.add("error"));
        robot.addRunExitCB(() -> calls.add("runExit"));
    }

    @Test
    void theRunsEndRunsTheNormalCallbacksThenTheRunExitOnes() throws Exception {
        List<String> calls = new CopyOnWriteArrayList<>();
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(room()), 7, ServerOptions.loopback())) {
            CompletableFuture<ArRobot.WaitState> exit = Background.supply("robot r1", () -> {
                ArRobot robot = new ArRobot("r1", "127.0.0.1", env.robotPort(), "p3dx.xml");
                listen(robot, calls);
                robot.runAsync();
                if (!robot.blockingConnect()) {
                    throw new IllegalStateException(robot.getConnectionError());
                }
                calls.add("connected " + robot.isConnected());
                robot.sleepSimulated(300);
                robot.endRun("done");
                return robot.waitForRunExit();
            });
            assertEquals(ArRobot.WaitState.WAIT_RUN_EXIT, exit.get(60, TimeUnit.SECONDS));
            env.await(60);
        }
        assertEquals(List.of("stabilizing", "connect true", "connected true", "normally", "runExit"), calls);
    }

    @Test
    void aRobotTheEnvironmentDropsRunsTheErrorCallbacks() throws Exception {
        ServerOptions options = new ServerOptions("127.0.0.1", 0, 0, 200, false, 500, 30_000, 0, 4 << 20)
                .withFirstStepsTimeoutMs(500);
        List<String> calls = new CopyOnWriteArrayList<>();
        AtomicBoolean spinning = new AtomicBoolean(true);
        String[] reason = new String[1];
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(room()), 7, options)) {
            CompletableFuture<Boolean> done = Background.supply("robot r1", () -> {
                ArRobot robot = new ArRobot("r1", "127.0.0.1", env.robotPort(), "p3dx.xml");
                listen(robot, calls);
                if (!robot.blockingConnect()) {
                    throw new IllegalStateException(robot.getConnectionError());
                }
                while (spinning.get() && robot.getRunEnd() == null) {
                    Thread.onSpinWait(); // never yielding: the Environment drops the robot
                }
                robot.sleepSimulated(100); // the next yield tells the program
                reason[0] = robot.getDropConnectionReason();
                return true;
            });
            try {
                assertTrue(done.get(60, TimeUnit.SECONDS));
            } finally {
                spinning.set(false);
            }
            env.await(60);
        }
        assertEquals(List.of("stabilizing", "connect true", "error"), calls);
        assertTrue(reason[0].contains("r1"), reason[0]);
    }
}
