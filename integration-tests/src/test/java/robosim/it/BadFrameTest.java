package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.dataformat.smile.databind.SmileMapper;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.aria.ArRobot;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.examples.wander.Wander;
import robosim.protocol.Bye;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotRequests;
import robosim.protocol.TimeStep;
import robosim.protocol.ViewerHello;
import robosim.protocol.Welcome;
import robosim.params.ParameterFileReader;

/**
 * A peer that breaks the protocol mid-run is closed with one log line naming it and the reason;
 * the Environment stays up and the other robot finishes its run.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class BadFrameTest {
    private static final int STEPS = 60;

    /** Runs r1 as a wander robot in this JVM and r2 as a raw peer that misbehaves after hello. */
    private static void misbehaveAsR2(Consumer<RawPeer> misbehave, String expectedReason) throws Exception {
        try (LogCapture log = new LogCapture("robosim.env.net");
             LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback().withMaxSteps(STEPS))) {
            Thread r1 = new Thread(() -> {
                ArRobot robot = new ArRobot("r1", "127.0.0.1", h.server.robotPort(), "p3dx");
                if (robot.blockingConnect()) {
                    robot.enableMotors();
                    new Wander(robot).run();
                }
            });
            r1.setDaemon(true);
            r1.start();
            try (RawPeer r2 = new RawPeer(h.server.robotPort())) {
                r2.send(new RobotHello("r2", "pioneer", ParameterFileReader.read(
                        LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p"))));
                assertInstanceOf(Welcome.class, r2.read());
                TimeStep first = (TimeStep) r2.read();
                r2.send(new RobotRequests(first.step(), List.of()));
                assertInstanceOf(TimeStep.class, r2.read());
                misbehave.accept(r2);
                assertTrue(r2.closedByPeer(), "the Environment closed r2's connection");
            }
            RunReport report = h.await();
            assertEquals("step limit " + STEPS + " reached", report.endReason(), "the run went on");
            RobotSummary r1Summary = report.robots().get(0);
            assertTrue(r1Summary.distance() > 100, "r1 kept driving: " + r1Summary);
            List<String> about = log.warnings().stream().filter(w -> w.contains("robot r2")).toList();
            assertEquals(1, about.size(), "one log line for r2: " + log.warnings());
            assertTrue(about.get(0).contains(expectedReason), about.get(0));
            r1.join(10_000);
        }
    }

    @Test
    void garbageFrameClosesOnlyThatRobot() throws Exception {
        misbehaveAsR2(r2 -> send(r2, new byte[] {0, 0, 0, 8, 'g', 'a', 'r', 'b', 'a', 'g', 'e', '!'}),
                "undecodable frame of 8 bytes");
    }

    @Test
    void oversizedFrameClosesOnlyThatRobot() throws Exception {
        misbehaveAsR2(r2 -> send(r2, new byte[] {0x7f, (byte) 0xff, (byte) 0xff, (byte) 0xff}),
                "frame of 2147483647 bytes exceeds the limit of 4194304 bytes");
    }

    @Test
    void requestsForAStepThatIsNotOpenCloseThatRobot() throws Exception {
        misbehaveAsR2(r2 -> send(r2, new RobotRequests(99, List.of())), "sent requests for step 99 while step 2 is open");
    }

    @Test
    void aNonFiniteVelocityClosesThatRobotBeforeItReachesTheSimulation() throws Exception {
        misbehaveAsR2(r2 -> send(r2, requestsFrame(2, Map.of("cmd", "vel", "vel", Double.NaN))),
                "sent an invalid request for step 2: NaN was supplied for vel: it must be a finite number");
    }

    @Test
    void aLaserIncrementNoSickHasClosesThatRobot() throws Exception {
        misbehaveAsR2(r2 -> send(r2, requestsFrame(2, Map.of("cmd", "laser", "on", true, "increment", 0.25,
                        "maxRange", 8000.0))),
                "0.25 was supplied for the laser increment: a SICK LMS200 scans at 1 or 0.5 degrees");
    }

    @Test
    void aMessageOfAnUnknownTypeClosesThatRobot() throws Exception {
        misbehaveAsR2(r2 -> send(r2, smileFrame(Map.of("type", "teleport"))), "unknown message type 'teleport'");
    }

    /**
     * Requests as raw bytes: a command whose values break its rule cannot be made as a record, so
     * it is written as the map a misbehaving client would encode.
     */
    private static byte[] requestsFrame(long step, Map<String, Object> command) {
        Map<String, Object> requests = new LinkedHashMap<>();
        requests.put("type", "robotRequests");
        requests.put("step", step);
        requests.put("commands", List.of(command));
        return smileFrame(requests);
    }

    private static byte[] smileFrame(Object value) {
        try {
            byte[] payload = new SmileMapper().writeValueAsBytes(value);
            return ByteBuffer.allocate(4 + payload.length).putInt(payload.length).put(payload).array();
        } catch (JsonProcessingException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Test
    void anUnknownRobotNameIsRefusedWithAReason() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback().withMaxSteps(1));
             RawPeer peer = new RawPeer(h.server.robotPort())) {
            peer.send(new RobotHello("r9", "pioneer", ParameterFileReader.read(
                    LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p"))));
            Message m = peer.read();
            assertInstanceOf(Bye.class, m);
            assertTrue(((Bye) m).reason().contains("has no robot named 'r9'"), ((Bye) m).reason());
            assertTrue(peer.closedByPeer());
        }
    }

    @Test
    void aViewerThatSendsGarbageIsClosedAndTheRunGoesOn() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback().withMaxSteps(STEPS));
             RawPeer viewer = new RawPeer(h.server.viewerPort())) {
            viewer.send(new ViewerHello("bad"));
            viewer.sendRaw(new byte[] {0, 0, 0, 3, 1, 2, 3});
            assertTrue(viewer.closedByPeer());
            for (String name : List.of("r1", "r2")) {
                Thread t = new Thread(() -> {
                    ArRobot robot = new ArRobot(name, "127.0.0.1", h.server.robotPort(), "p3dx");
                    if (robot.blockingConnect()) {
                        robot.enableMotors();
                        new Wander(robot).run();
                    }
                });
                t.setDaemon(true);
                t.start();
            }
            assertEquals("step limit " + STEPS + " reached", h.await().endReason());
        }
    }

    private static void send(RawPeer peer, Object what) {
        try {
            if (what instanceof byte[] bytes) {
                peer.sendRaw(bytes);
            } else {
                peer.send((Message) what);
            }
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
