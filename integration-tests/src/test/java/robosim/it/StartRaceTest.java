package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.ServerSocket;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.ExtendWith;
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
import robosim.protocol.Await;
import robosim.protocol.RunSecret;

/**
 * Robots started before their Environment: they look their run secret up once connected, so an
 * earlier run's file does not get them refused; a refusal of a secret that has changed since is
 * tried again; a secret refused again ends the robot at once, and the Environment's waiting line
 * names the refused robots. Each race is made the same every time: a robot is known to have begun
 * (it appears in a {@link RunEndWatch}) before the Environment starts, and the file changes from
 * the Environment's own log handler.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
@ExtendWith(NoSecretProperty.class)
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
    private static void awaitConnecting(RunEndWatch watch, List<String> names) {
        Await.until(Duration.ofSeconds(60), "the robots begin to connect", () -> watch.beforeFirstStep().stream()
                .map(RunEndWatch.BeforeFirstStep::robot).toList().containsAll(names));
    }

    @Test
    void robotsStartedBeforeTheEnvironmentFindItsSecretOnceConnectedAndAreNeverRefused() throws Exception {
        int port = freePort();
        String secret = RunSecret.create();
        // an earlier run's file: what a robot started first finds before the Environment is there
        RunSecret.write(RunSecret.fileFor(port), RunSecret.create());
        try (RunEndWatch watch = RunEndWatch.open()) {
            CompletableFuture<ArRobot> r1 = robot("r1", port);
            CompletableFuture<ArRobot> r2 = robot("r2", port);
            awaitConnecting(watch, List.of("r1", "r2"));
            // the Environment starts now, as env does: its secret written before it listens
            RunSecret.write(RunSecret.fileFor(port), secret);
            ServerOptions options = new ServerOptions("127.0.0.1", port, 0, 30, false, 10_000, 60_000, 0, 4 << 20)
                    .withAccess(Access.secret(secret));
            try (LogCapture log = new LogCapture("robosim.env.net");
                 LocalEnvironment h = new LocalEnvironment(LocalEnvironment.shipped("empty-room.xml"), 1, options)) {
                RunReport report = h.await();
                assertEquals("step limit 30 reached", report.endReason());
                for (CompletableFuture<ArRobot> r : List.of(r1, r2)) {
                    ArRobot robot = r.get(60, TimeUnit.SECONDS);
                    assertNull(robot.getConnectionError());
                    assertEquals(RunEnd.Kind.RUN_ENDED, robot.getRunEnd().kind());
                }
                assertTrue(log.warnings().stream().noneMatch(w -> w.contains("refusing")), "none refused: "
                        + log.warnings());
            }
        }
    }

    /**
     * The Environment refuses a robot's secret, and by the time the robot reads the refusal another
     * secret is in the file (here written by the log handler that sees the refusal, before the bye
     * goes out): the robot tries again with it and joins.
     */
    @Test
    void aRefusalOfASecretThatHasChangedSinceIsTriedAgainAndTheRobotJoins() throws Exception {
        String secret = RunSecret.create();
        ServerOptions options = ServerOptions.loopback().withMaxSteps(10).withAccess(Access.secret(secret));
        Logger envLog = Logger.getLogger("robosim.env.net");
        try (LogCapture log = new LogCapture("robosim.env.net");
             LocalEnvironment h = new LocalEnvironment(LocalEnvironment.shipped("empty-room.xml"), 1, options)) {
            Path file = RunSecret.fileFor(h.robotPort());
            RunSecret.write(file, RunSecret.create());
            Handler writesTheSecret = new Handler() {
                @Override
                public void publish(LogRecord r) {
                    if (r.getMessage().startsWith("refusing robot")) {
                        try {
                            RunSecret.write(file, secret);
                        } catch (java.io.IOException e) {
                            throw new java.io.UncheckedIOException(e);
                        }
                    }
                }

                @Override
                public void flush() {
                }

                @Override
                public void close() {
                }
            };
            envLog.addHandler(writesTheSecret);
            try {
                CompletableFuture<ArRobot> r1 = robot("r1", h.robotPort());
                CompletableFuture<ArRobot> r2 = robot("r2", h.robotPort());
                assertEquals("step limit 10 reached", h.await().endReason());
                for (CompletableFuture<ArRobot> r : List.of(r1, r2)) {
                    assertEquals(RunEnd.Kind.RUN_ENDED, r.get(60, TimeUnit.SECONDS).getRunEnd().kind());
                }
                assertTrue(log.warnings().stream().anyMatch(w -> w.contains(RunSecret.REFUSED_WRONG)),
                        "a robot was refused first: " + log.warnings());
            } finally {
                envLog.removeHandler(writesTheSecret);
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
            Await.until("a status names the refused robot",
                    () -> statuses.stream().anyMatch(s -> s.refused().containsKey("r1")));
            RunProgress.Status s = statuses.stream().filter(x -> x.refused().containsKey("r1")).findFirst().orElseThrow();
            assertEquals(Map.of("r1", RunSecret.REFUSED_WRONG), s.refused());
            assertEquals(RunProgress.Phase.CONNECTING, s.phase());
            assertFalse(run.isDone(), "the Environment still waits for its robots");
        }
    }
}
