package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.aria.ArRobot;
import robosim.cli.Background;
import robosim.env.core.Simulation;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.RunProgress;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.examples.wander.Wander;
import robosim.protocol.Await;
import robosim.protocol.FrameReader;

/**
 * The Environment's progress hook: while it waits for robots it says which are missing, and how
 * long of how long it has waited; while it runs, the step, the simulated time and the robots; at
 * most once per interval. A listener that fails is dropped and the run goes on.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class RunProgressTest {
    private static void wander(int port, String name) {
        Thread t = new Thread(() -> {
            ArRobot robot = new ArRobot(name, "127.0.0.1", port, "p3dx");
            if (robot.blockingConnect()) {
                robot.enableMotors();
                new Wander(robot).run();
            }
        }, "wander-" + name);
        t.setDaemon(true);
        t.start();
    }

    private static CompletableFuture<RunReport> run(EnvironmentServer server) {
        return Background.supply("environment", () -> {
            try {
                return server.run();
            } catch (InterruptedException e) {
                throw new IllegalStateException(e);
            }
        });
    }

    /** @return whether the server told, while it waited for robots, a status that passes the test */
    private static boolean told(List<RunProgress.Status> seen, Predicate<RunProgress.Status> test) {
        synchronized (seen) {
            return seen.stream().anyMatch(s -> s.phase() == RunProgress.Phase.CONNECTING && test.test(s));
        }
    }

    @Test
    void theServerSaysWhomItWaitsForThenHowFarTheRunHasCome() throws Exception {
        List<RunProgress.Status> seen = new ArrayList<>();
        List<Long> at = new ArrayList<>();
        Simulation sim = new Simulation(LocalEnvironment.shipped("empty-room.xml"), 1);
        ServerOptions realtime = new ServerOptions("127.0.0.1", 0, 0, 30, true, 10_000, 60_000, 0,
                FrameReader.DEFAULT_MAX_FRAME);
        try (EnvironmentServer server = new EnvironmentServer(sim, realtime)) {
            server.setProgress(s -> {
                synchronized (seen) {
                    seen.add(s);
                    at.add(System.nanoTime());
                }
            }, 100);
            server.bind();
            CompletableFuture<RunReport> report = run(server);
            Await.until("a status before any robot connects", () -> told(seen, s -> s.connected() == 0));
            wander(server.robotPort(), "r1");
            Await.until("a status with r1 connected and r2 missing", () -> told(seen, s -> s.connected() == 1));
            wander(server.robotPort(), "r2");
            assertEquals("step limit 30 reached", report.get(60, TimeUnit.SECONDS).endReason());
        }
        synchronized (seen) {
            RunProgress.Status first = seen.get(0);
            assertEquals(RunProgress.Phase.CONNECTING, first.phase());
            assertEquals(List.of("r1", "r2"), first.waitingFor());
            assertEquals(0, first.connected());
            assertEquals(TimeUnit.SECONDS.toNanos(60), first.waitLimitNanos());
            assertTrue(seen.stream().anyMatch(s -> s.phase() == RunProgress.Phase.CONNECTING
                    && s.waitingFor().equals(List.of("r2")) && s.connected() == 1), "r1 connected, r2 missing: " + seen);
            // running, or in a step waiting (briefly) for the robots' requests
            List<RunProgress.Status> running = seen.stream().filter(s -> s.phase() != RunProgress.Phase.CONNECTING)
                    .toList();
            assertTrue(running.size() >= 10, "30 steps of 100 ms, told at most every 100 ms: " + running.size());
            long last = -1;
            for (RunProgress.Status s : running) {
                assertTrue(s.step() >= last, "steps go forward");
                last = s.step();
                assertEquals(s.step() * 100, s.timeMs());
                assertEquals(30, s.maxSteps());
                assertEquals(2, s.connected());
                assertTrue(s.runNanos() > 0 || s.step() == 0);
            }
            for (int i = 1; i < at.size(); i++) {
                assertTrue(at.get(i) - at.get(i - 1) >= TimeUnit.MILLISECONDS.toNanos(95), "at most once per interval");
            }
        }
    }

    @Test
    void aListenerThatFailsIsDroppedAndTheRunGoesOn() throws Exception {
        int[] calls = {0};
        Simulation sim = new Simulation(LocalEnvironment.shipped("empty-room.xml"), 1);
        try (EnvironmentServer server = new EnvironmentServer(sim, ServerOptions.loopback().withMaxSteps(20))) {
            server.setProgress(s -> {
                calls[0]++;
                throw new IllegalStateException("a broken progress line");
            }, 1);
            server.bind();
            CompletableFuture<RunReport> report = run(server);
            wander(server.robotPort(), "r1");
            wander(server.robotPort(), "r2");
            assertEquals("step limit 20 reached", report.get(60, TimeUnit.SECONDS).endReason());
        }
        assertEquals(1, calls[0]);
    }
}
