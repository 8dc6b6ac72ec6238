package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.ServerSocket;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.cli.Background;
import robosim.env.core.Simulation;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.Access;
import robosim.env.net.RunProgress;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.hw.RunEnd;
import robosim.hw.RunEndWatch;
import robosim.protocol.RunSecret;

/**
 * Robots started before their Environment has written its run secret: they look for it again
 * when refused, and join; a secret that is refused again ends the robot at once, and the
 * Environment's waiting line names the refused robots. Each robot is known to have read its secret
 * (it appears in a {@link RunEndWatch}) before the Environment writes its own, so the race is the
 * same every time.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class StartRaceTest {
    @TempDir
    Path dir;
    private String tokenDirBefore;

    @BeforeEach
    void tokensInTheTestsFolder() {
        tokenDirBefore = System.getProperty(RunSecret.DIR_PROPERTY);
        System.setProperty(RunSecret.DIR_PROPERTY, dir.resolve("tokens").toString());
    }

    @AfterEach
    void tokensBack() {
        if (tokenDirBefore == null) {
            System.clearProperty(RunSecret.DIR_PROPERTY);
        } else {
            System.setProperty(RunSecret.DIR_PROPERTY, tokenDirBefore);
        }
    }

    private static int freePort() throws Exception {
        try (ServerSocket s = new ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    /** Starts a robot that connects and drives a little until the run ends. */
    private static CompletableFuture<ArRobot> robot(String name, int port) {
        return Background.supply("robot-" + name, () -> {
            ArRobot r = new ArRobot(name, "127.0.0.1", port, "p3dx");
            if (r.blockingConnect()) {
                r.enableMotors();
                r.setVel(100);
                while (r.isConnected()) {
                    r.sleepSimulated(100);
                }
            }
            return r;
        });
    }

    /** Waits until the watch follows robots of these names: each has read its secret and begun to connect. */
    private static void awaitConnecting(RunEndWatch watch, List<String> names) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!watch.beforeFirstStep().stream().map(RunEndWatch.BeforeFirstStep::robot).toList().containsAll(names)) {
            assertTrue(System.nanoTime() < deadline, "the robots began to connect within 60 s");
            Thread.sleep(10);
        }
    }

    @Test
    void robotsThatFoundAnEarlierRunsSecretJoinOnceTheEnvironmentHasWrittenItsOwn() throws Exception {
        int port = freePort();
        String stale = RunSecret.create();
        String secret = RunSecret.create();
        RunSecret.write(RunSecret.fileFor(port), stale);
        try (RunEndWatch watch = RunEndWatch.open()) {
            CompletableFuture<ArRobot> r1 = robot("r1", port);
            CompletableFuture<ArRobot> r2 = robot("r2", port);
            awaitConnecting(watch, List.of("r1", "r2"));
            // the Environment starts now, as env does: its secret written before it reads a hello
            RunSecret.write(RunSecret.fileFor(port), secret);
            ServerOptions options = new ServerOptions("127.0.0.1", port, 0, 30, false, 10_000, 60_000, 0, 4 << 20)
                    .withAccess(Access.secret(secret));
            try (LogCapture log = new LogCapture("robosim.env.net");
                 LocalEnvironment h = new LocalEnvironment(LocalEnvironment.shipped("empty-room.xml"), 1, options)) {
                RunReport report = h.await();
                assertEquals("step limit 30 reached", report.endReason());
                for (CompletableFuture<ArRobot> r : List.of(r1, r2)) {
                    ArRobot robot = r.get(60, TimeUnit.SECONDS);
                    assertNull(robot.getConnectionError(), "connected after the refusal of the stale secret");
                    assertEquals(RunEnd.Kind.RUN_ENDED, robot.getRunEnd().kind());
                }
                assertTrue(log.warnings().stream().anyMatch(w -> w.contains(RunSecret.REFUSED_WRONG)),
                        "the stale secret was refused first: " + log.warnings());
            }
        }
    }

    @Test
    void aSecretRefusedAgainEndsTheRobotAtOnceAndTheWaitingLineNamesIt() throws Exception {
        String secret = RunSecret.create();
        ServerOptions options = ServerOptions.loopback().withMaxSteps(5).withAccess(Access.secret(secret));
        List<RunProgress.Status> statuses = new CopyOnWriteArrayList<>();
        Simulation sim = new Simulation(LocalEnvironment.shipped("empty-room.xml"), 1);
        try (LogCapture log = new LogCapture("robosim.env.net");
             EnvironmentServer server = new EnvironmentServer(sim, options)) {
            server.setProgress(statuses::add, 10);
            server.bind();
            CompletableFuture<RunReport> run = Background.supply("environment", () -> {
                try {
                    return server.run();
                } catch (InterruptedException | RuntimeException e) {
                    return null;
                }
            });
            // a file that is not this run's, and stays so: the refusal cannot clear
            RunSecret.write(RunSecret.fileFor(server.robotPort()), RunSecret.create());
            long started = System.nanoTime();
            ArRobot r1 = robot("r1", server.robotPort()).get(60, TimeUnit.SECONDS);
            long tookMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
            assertFalse(r1.isConnected());
            assertEquals(RunEnd.Kind.REFUSED, r1.getRunEnd().kind());
            assertTrue(r1.getConnectionError().contains(RunSecret.REFUSED_WRONG), r1.getConnectionError());
            // not the connect timeout's 60 s: refused once, looked again, found the same, gave up
            assertTrue(tookMs < 30_000, "ended at once, not at the connect timeout: " + tookMs + " ms");
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (statuses.stream().noneMatch(s -> s.refused().containsKey("r1"))) {
                assertTrue(System.nanoTime() < deadline, "a status names the refused robot");
                Thread.sleep(10);
            }
            RunProgress.Status s = statuses.stream().filter(x -> x.refused().containsKey("r1")).findFirst().orElseThrow();
            assertEquals(Map.of("r1", RunSecret.REFUSED_WRONG), s.refused());
            assertEquals(RunProgress.Phase.CONNECTING, s.phase());
            assertFalse(run.isDone(), "the Environment still waits for its robots");
        }
    }
}
