package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.Bye;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotRequests;
import robosim.protocol.RobotState;
import robosim.protocol.Snapshot;
import robosim.protocol.TimeStep;
import robosim.protocol.ViewerHello;
import robosim.protocol.Welcome;

/**
 * How {@code robosim robot} ends when the run ends, when the Environment refuses its robot, dies, or
 * goes silent: one line naming the robot, the Environment, the last step and the reason, and an exit
 * code for each (0, 4, 3, 3). Every program is the shipped wander robot, in a JVM of its own.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class RobotProgramEndsTest {
    private static final String WANDER = "robosim.examples.wander.Wander";

    @TempDir
    Path dir;

    /** A 6 m room with the one robot r1. */
    private Path oneRobotWorld() throws Exception {
        Path p3dx = LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p").toAbsolutePath();
        Path world = dir.resolve("one-robot.xml");
        Files.writeString(world, """
                <?xml version="1.0" encoding="UTF-8"?>
                <world name="one-robot" width="6000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="1500" y="1500" th="45" params="%s"/>
                </world>
                """.formatted(p3dx));
        return world;
    }

    /**
     * @return the lines that name the text, without the progress lines a slow start prints ("robot r1
     *         is waiting for the Environment ... - 2 s"), which come or not with the machine's load
     */
    private static List<String> linesWith(LauncherJvm jvm, String text) {
        return jvm.lines().stream().filter(l -> l.contains(text) && !l.matches(".* - \\d+ s$")).toList();
    }

    @Test
    void theEnvironmentKilledMidRunEndsTheRobotProgramWithExit3AndOneLineSayingSo() throws Exception {
        try (LauncherJvm env = new LauncherJvm("env", oneRobotWorld().toString(), "--port", "0", "--viewer-port", "0",
                "--realtime", "--wait-viewers", "1", "--no-token")) {
            String listening = env.awaitLine(l -> l.startsWith("Environment: world one-robot, robots on "), 60);
            Matcher m = Pattern.compile("robots on 127\\.0\\.0\\.1:(\\d+), viewers on 127\\.0\\.0\\.1:(\\d+)")
                    .matcher(listening);
            assertTrue(m.find(), listening);
            String port = m.group(1);
            try (LauncherJvm robot = new LauncherJvm("robot", WANDER, "r1", "127.0.0.1", port);
                 RawPeer viewer = new RawPeer(Integer.parseInt(m.group(2)))) {
                viewer.send(new ViewerHello("test"));
                Message seen;
                do {
                    seen = viewer.read();
                    assertTrue(seen != null && !(seen instanceof Bye), "the viewer was let in: " + seen);
                } while (!(seen instanceof Snapshot s && s.step() >= 3));

                env.kill();

                assertEquals(3, robot.awaitExit(30), robot.output());
                List<String> said = linesWith(robot, "lost the Environment");
                assertEquals(1, said.size(), robot.output());
                Matcher line = Pattern.compile("robosim robot: robot r1 lost the Environment at 127\\.0\\.0\\.1:" + port
                        + " after step (\\d+): .*").matcher(said.get(0));
                assertTrue(line.matches() && Long.parseLong(line.group(1)) >= 3, "mid-run: " + said.get(0));
                assertTrue(said.get(0).endsWith(": it closed the connection without a bye")
                        || said.get(0).contains(": the connection failed: "), said.get(0));
            }
        }
    }

    @Test
    void anEnvironmentThatGoesSilentIsDeclaredLostAfterTheLostTime() throws Exception {
        MessageCodec codec = new MessageCodec();
        try (ServerSocket listener = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            listener.setSoTimeout(60_000);
            int port = listener.getLocalPort();
            try (LauncherJvm robot = new LauncherJvm("robot", "--lost-after", "1000", WANDER, "r1", "127.0.0.1",
                    Integer.toString(port));
                 Socket peer = listener.accept()) {
                peer.setSoTimeout(30_000);
                FrameReader in = new FrameReader(peer.getInputStream(), codec, FrameReader.DEFAULT_MAX_FRAME);
                FrameWriter out = new FrameWriter(peer.getOutputStream(), codec);
                assertEquals("r1", assertInstanceOf(RobotHello.class, in.read()).name());
                RobotState start = new RobotState(0, 0, 1500, 1500, 45, 0, 0, 0, 0, false, 0);
                out.write(new Welcome("r1", 100, start));
                out.write(new TimeStep(1, 0, start));
                long silentSince = System.nanoTime(); // the last the Environment sends
                assertEquals(1, assertInstanceOf(RobotRequests.class, in.read()).step());

                // the Environment says nothing more, and keeps the connection open
                assertEquals(3, robot.awaitExit(30), robot.output());
                long tookMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - silentSince);
                assertTrue(tookMs >= 1000, "declared lost after " + tookMs + " ms, before the lost time");
                assertEquals(List.of("robosim robot: robot r1 lost the Environment at 127.0.0.1:" + port
                        + " after step 1: it sent nothing, neither a step nor a keep-alive, for 1000 ms"),
                        linesWith(robot, "r1"), robot.output());
            }
        }
    }

    @Test
    void aRunThatEndsEndsTheRobotProgramWithExit0AndTheReason() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment(WorldReader.read(oneRobotWorld()), 1,
                ServerOptions.loopback().withMaxSteps(20));
             LauncherJvm robot = new LauncherJvm("robot", WANDER, "r1", "127.0.0.1", Integer.toString(h.robotPort()))) {
            assertEquals("step limit 20 reached", h.await().endReason());
            assertEquals(0, robot.awaitExit(30), robot.output());
            assertEquals(List.of("robot r1 ran to the end of the run at 127.0.0.1:" + h.robotPort()
                    + " after step 20: step limit 20 reached"), linesWith(robot, "r1"), robot.output());
        }
    }

    @Test
    void aRobotKeptInTheRunAfterMainReturnsRunsUntilTheRunEnds() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment(WorldReader.read(oneRobotWorld()), 1,
                ServerOptions.loopback().withMaxSteps(20));
             LauncherJvm robot = new LauncherJvm("robot", TaskDriver.class.getName(), "r1", "127.0.0.1",
                     Integer.toString(h.robotPort()))) {
            RunReport report = h.await();
            assertEquals("step limit 20 reached", report.endReason());
            assertEquals(Optional.empty(), report.departure("r1"), "r1 ran to the end");
            assertTrue(report.robots().get(0).distance() > 100, "its task drove it: " + report.robots().get(0));
            assertEquals(0, robot.awaitExit(30), robot.output());
            assertEquals(List.of("robot r1 ran to the end of the run at 127.0.0.1:" + h.robotPort()
                    + " after step 20: step limit 20 reached"), linesWith(robot, "r1"), robot.output());
        }
    }

    @Test
    void aRobotTheEnvironmentRefusesEndsItsProgramWithExit4() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback().withMaxSteps(1));
             LauncherJvm robot = new LauncherJvm("robot", WANDER, "r9", "127.0.0.1", Integer.toString(h.robotPort()))) {
            assertEquals(4, robot.awaitExit(60), robot.output());
            assertTrue(robot.lines().contains("robosim robot: robot r9 was refused by the Environment at 127.0.0.1:"
                    + h.robotPort() + " before step 1: world empty-room has no robot named 'r9'"), robot.output());
            h.wanderers();
            assertEquals("step limit 1 reached", h.await().endReason(), "the world's own robots ran");
        }
    }
}
