package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import robosim.cli.Main;
import robosim.cli.RobotProcesses;
import robosim.env.core.Simulation;
import robosim.env.net.Access;
import robosim.env.net.EnvironmentServer;
import robosim.env.net.Limits;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.protocol.Await;
import robosim.protocol.Bye;
import robosim.protocol.ControlHello;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldDescription;
import robosim.protocol.RobotHello;
import robosim.protocol.RunSecret;
import robosim.protocol.Welcome;

/**
 * The access rules and caps on a live Environment: the run secret, from a robot program that is
 * given it without a line of code, and from the files {@code env} writes; the hello deadline; the
 * cap on connections that have not said hello; no listening beyond loopback without a secret.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
@ExtendWith(NoSecretProperty.class)
class AccessAndCapsTest {
    private static final String SECRET = RunSecret.create();

    @TempDir
    Path dir;

    private static RobotHello hello(Simulation sim, String name, String token) {
        return new RobotHello(name, "pioneer", sim.world().robots().get(0).parameters(), token);
    }

    @Test
    void robotProgramsGivenTheSecretRunAndAStrangerCannotTakeAName() throws Exception {
        ServerOptions options = ServerOptions.loopback().withMaxSteps(20).withAccess(Access.secret(SECRET));
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", options);
             RawPeer stranger = new RawPeer(h.robotPort())) {
            stranger.send(hello(h.sim, "r2", null));
            Bye bye = assertInstanceOf(Bye.class, stranger.read());
            assertTrue(bye.reason().startsWith("refused: robot r2 presented no run secret"), bye.reason());

            List<Process> robots = new ArrayList<>();
            for (String name : List.of("r1", "r2")) {
                robots.add(RobotProcesses.start(SonarDriver.class.getName(), name, h.robotPort(), SECRET,
                        dir.resolve(name + ".log")));
            }
            try {
                RunReport report = h.await();
                assertEquals("step limit 20 reached", report.endReason());
                for (Process p : robots) {
                    assertTrue(p.waitFor(30, TimeUnit.SECONDS));
                }
            } finally {
                RobotProcesses.stop(robots);
            }
        }
    }

    @Test
    void aViewerWithoutTheSecretIsToldWhyItWasRefused() throws Exception {
        ServerOptions options = ServerOptions.loopback().withAccess(Access.secret(SECRET));
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", options)) {
            StringWriter err = new StringWriter();
            CommandLine cl = Main.commandLine();
            cl.setOut(new PrintWriter(new StringWriter()));
            cl.setErr(new PrintWriter(err, true));

            int code = cl.execute("viewer", "--port", Integer.toString(h.viewerPort()), "--png-dir",
                    dir.resolve("png").toString());

            assertEquals(1, code);
            assertTrue(err.toString().contains("sent no world: refused: viewer png:png presented no run secret"),
                    err.toString());
        }
    }

    @Test
    void aRobotWaitingForARunThatNeverStartsIsToldWhy() throws Exception {
        ServerOptions options = new ServerOptions("127.0.0.1", 0, 0, 0, false, 10_000, 1_000, 0, 4 << 20);
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", options);
             RawPeer r1 = new RawPeer(h.robotPort())) {
            r1.send(hello(h.sim, "r1", null));
            assertInstanceOf(Welcome.class, r1.read());

            robosim.protocol.Message m;
            do {
                m = r1.read();
            } while (m instanceof robosim.protocol.KeepAlive);
            assertEquals("the run did not start: robots [r2] and 0 viewer(s) did not connect within 1 s",
                    assertInstanceOf(Bye.class, m).reason());
        }
    }

    @Test
    void aConnectionThatSaysNoHelloIsClosedAtTheDeadline() throws Exception {
        ServerOptions options = ServerOptions.loopback().withLimits(Limits.defaults().withHelloDeadlineMs(300));
        try (LogCapture log = new LogCapture("robosim.env.net");
             LocalEnvironment h = new LocalEnvironment("empty-room.xml", options);
             RawPeer silent = new RawPeer(h.robotPort())) {
            assertTrue(silent.closedByPeer());
            assertTrue(log.warnings().stream().anyMatch(w -> w.matches(
                    "closing a robot connection from /127\\.0\\.0\\.1:\\d+: it said no hello within 300 ms")),
                    log.warnings().toString());
        }
    }

    @Test
    void anIdleControlClientIsClosedAndAViewerThatReadsIsNot() throws Exception {
        ServerOptions options = ServerOptions.loopback().withLimits(Limits.defaults().withIdleTimeoutMs(300));
        try (LogCapture log = new LogCapture("robosim.env.net");
             LocalEnvironment h = new LocalEnvironment("empty-room.xml", options);
             RawPeer control = new RawPeer(h.viewerPort());
             RawPeer viewer = new RawPeer(h.viewerPort())) {
            control.send(new ControlHello("idle", null));
            viewer.send(new ViewerHello("watching"));
            assertInstanceOf(WorldDescription.class, viewer.read());

            assertTrue(control.closedByPeer());
            assertTrue(log.warnings().contains("closing control client idle: it sent nothing for 300 ms (--idle-timeout)"),
                    log.warnings().toString());
            assertTrue(log.warnings().stream().noneMatch(w -> w.contains("watching")), log.warnings().toString());
        }
    }

    @Test
    void silentConnectionsHoldingEverySlotMakeRoomForARobotLongBeforeTheirDeadline() throws Exception {
        ServerOptions options = ServerOptions.loopback()
                .withLimits(Limits.defaults().withMaxPending(3).withHelloDeadlineMs(60_000));
        try (LogCapture log = new LogCapture("robosim.env.net");
             LocalEnvironment h = new LocalEnvironment("empty-room.xml", options)) {
            List<RawPeer> silent = new ArrayList<>();
            try {
                for (int i = 0; i < 3; i++) {
                    silent.add(new RawPeer(h.robotPort()));
                }
                try (RawPeer robot = new RawPeer(h.robotPort())) {
                    robot.send(hello(h.sim, "r1", null));
                    // welcomed once the oldest silent connection has been silent a second, not after 60 s
                    assertEquals("r1", assertInstanceOf(Welcome.class, robot.read()).name());
                    assertTrue(silent.get(0).closedByPeer(), "the oldest silent connection made room");
                }
            } finally {
                for (RawPeer p : silent) {
                    p.close();
                }
            }
            // the first line of the flood says why accepting waited; the closing that made room is
            // counted with it in the period's count (the same warning kind)
            assertTrue(log.warnings().get(0).startsWith("3 connections have not said hello yet"), log.warnings().toString());
        }
    }

    @Test
    void connectionsWithoutAHelloAreCappedAndARobotStillGetsInOnceTheyTimeOut() throws Exception {
        ServerOptions options = ServerOptions.loopback()
                .withLimits(Limits.defaults().withMaxPending(3).withHelloDeadlineMs(1000));
        try (LogCapture log = new LogCapture("robosim.env.net");
             LocalEnvironment h = new LocalEnvironment("empty-room.xml", options)) {
            List<RawPeer> idle = new ArrayList<>();
            try {
                for (int i = 0; i < 3; i++) {
                    idle.add(new RawPeer(h.robotPort()));
                }
                // the kernel takes the connection; the Environment waits to accept it
                try (RawPeer robot = new RawPeer(h.robotPort())) {
                    robot.send(hello(h.sim, "r1", null));
                    assertEquals("r1", assertInstanceOf(Welcome.class, robot.read()).name());
                    for (RawPeer p : idle) {
                        assertTrue(p.closedByPeer(), "an idle connection was closed at the deadline");
                    }
                }
            } finally {
                for (RawPeer p : idle) {
                    p.close();
                }
            }
            assertTrue(log.warnings().stream().anyMatch(w -> w.startsWith("3 connections have not said hello yet,"
                    + " the most this Environment allows (--max-pending)")), log.warnings().toString());
        }
    }

    @Test
    void listeningBeyondLoopbackWithoutASecretIsRefusedSayingWhy() {
        Simulation sim = new Simulation(LocalEnvironment.shipped("empty-room.xml"), 1);
        ServerOptions options = new ServerOptions("0.0.0.0", 0, 0, 0, false, 10_000, 10_000, 0, 4 << 20);
        try (EnvironmentServer server = new EnvironmentServer(sim, options)) {
            IllegalStateException e = assertThrows(IllegalStateException.class, server::bind);
            assertTrue(e.getMessage().startsWith("refusing to listen on 0.0.0.0 without a run secret: anyone who can"
                    + " reach that address could join, watch and change the run"), e.getMessage());
        }
    }

    @Test
    void theEnvCommandRefusesToListenBeyondLoopbackWithoutASecret() {
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(new StringWriter()));
        cl.setErr(new PrintWriter(err, true));

        int code = cl.execute("env", LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml").toString(),
                "--no-token", "--bind", "0.0.0.0", "--port", "0", "--viewer-port", "0");

        assertEquals(2, code);
        assertTrue(err.toString().startsWith("robosim env: refusing to listen on 0.0.0.0 without a run secret"),
                err.toString());
    }

    @Test
    void theEnvCommandWritesItsSecretForItsOwnerAndClientsFindItByPort() throws Exception {
        String before = System.getProperty(RunSecret.DIR_PROPERTY);
        System.setProperty(RunSecret.DIR_PROPERTY, dir.resolve("tokens").toString());
        StringWriter out = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(new StringWriter(), true));
        try {
            CompletableFuture<Integer> env = CompletableFuture.supplyAsync(() -> cl.execute("env",
                    LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml").toString(),
                    "--port", "0", "--viewer-port", "0", "--steps", "1", "--connect-timeout", "60"));
            int port = awaitPort(out);
            Path file = dir.resolve("tokens").resolve(Integer.toString(port));
            assertTrue(out.toString().contains("Run secret: in " + file), out.toString());
            if (file.getFileSystem().supportedFileAttributeViews().contains("posix")) {
                assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));
            }
            String found = RunSecret.find(null, "127.0.0.1", port);
            Simulation sim = new Simulation(LocalEnvironment.shipped("empty-room.xml"), 1);
            try (RawPeer r1 = new RawPeer(port); RawPeer r2 = new RawPeer(port)) {
                r1.send(hello(sim, "r1", found));
                r2.send(hello(sim, "r2", found));
                assertInstanceOf(Welcome.class, r1.read());
                assertInstanceOf(Welcome.class, r2.read());
            }
            assertEquals(0, env.get(60, TimeUnit.SECONDS), out.toString());
            assertTrue(Files.notExists(file), "the secret's file is removed when the run ends");
        } finally {
            if (before == null) {
                System.clearProperty(RunSecret.DIR_PROPERTY);
            } else {
                System.setProperty(RunSecret.DIR_PROPERTY, before);
            }
        }
    }

    /** Waits (bounded) for env's line naming its robot port. */
    private static int awaitPort(StringWriter out) {
        Pattern robots = Pattern.compile("robots on 127\\.0\\.0\\.1:(\\d+)");
        return Await.value(Await.PATIENCE, "env prints its robot port", () -> {
            Matcher m = robots.matcher(out.toString());
            return m.find() ? Integer.valueOf(m.group(1)) : null;
        });
    }
}
