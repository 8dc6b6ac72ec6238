package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.hw.FakeLink.WAIT_MS;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Await;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.LinkHello;
import robosim.protocol.LinkRequests;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotHello;
import robosim.protocol.TimeSteps;
import robosim.protocol.Welcome;

/**
 * Robots of one JVM on a shared link, against an Environment played by the test over loopback:
 * one connection for all, one frame of requests per step when all yield, the ready robots' requests
 * first when one is late, and one robot ended without the others.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class SharedLinkTest {
    private static final HardwareOptions OPTIONS = new HardwareOptions(WAIT_MS, WAIT_MS, 60_000);
    /** Every robot of the test on the shared link, apart from any other robot of the JVM. */
    private final RobotRuntime runtime = RobotRuntime.create("shared-link-test",
            RuntimeChoices.defaults().withLinks(EnvironmentLinks.Mode.SHARED));
    private final MessageCodec codec = new MessageCodec();
    private final RobotCode code = new RobotCode();
    private ServerSocket listener;
    private Socket env;
    private FrameReader in;
    private FrameWriter out;
    private HardwareSimulator r1;
    private HardwareSimulator r2;

    @BeforeEach
    void listen() throws IOException {
        listener = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
        listener.setSoTimeout((int) WAIT_MS);
    }

    @AfterEach
    void close() throws Exception {
        try {
            if (env != null) {
                env.close();
            }
            listener.close();
        } finally {
            code.close();
        }
    }

    private HardwareSimulator hardware(String name) {
        return new HardwareSimulator(new RobotHello(name, "pioneer", TestRobot.PARAMETERS), r -> { }, OPTIONS, runtime);
    }

    /** Starts robot code that connects {@code hw}, then runs {@code body}. */
    private void robot(HardwareSimulator hw, RobotCode.Body body) {
        code.start("code-" + hw.toString(), () -> {
            hw.connect("127.0.0.1", listener.getLocalPort());
            body.run();
        });
    }

    /** Accepts the link, reads its hello and the robots' hellos, and welcomes each. */
    private void accept(String... robots) throws IOException {
        env = listener.accept();
        env.setSoTimeout((int) WAIT_MS);
        in = new FrameReader(env.getInputStream(), codec, FrameReader.DEFAULT_MAX_FRAME);
        out = new FrameWriter(env.getOutputStream(), codec);
        assertInstanceOf(LinkHello.class, in.read());
        for (int i = 0; i < robots.length; i++) {
            RobotHello hello = assertInstanceOf(RobotHello.class, in.read());
            out.write(new Welcome(hello.name(), 100, FakeLink.state(0)));
        }
    }

    private void steps(long step, String... robots) throws IOException {
        out.write(new TimeSteps(step, (step - 1) * 100, List.of(robots).stream()
                .map(r -> new TimeSteps.ForRobot(r, FakeLink.state(step - 1))).toList()));
    }

    private Map<String, List<Command>> requests(long step) throws IOException {
        LinkRequests r = assertInstanceOf(LinkRequests.class, in.read());
        assertEquals(step, r.step());
        return r.robots().stream().collect(Collectors.toMap(LinkRequests.ForRobot::robot,
                LinkRequests.ForRobot::commands));
    }

    @Test
    void twoRobotsShareOneConnectionAndAnswerEachStepInOneFrame() throws Exception {
        r1 = hardware("r1");
        r2 = hardware("r2");
        robot(r1, () -> {
            r1.request(new RobotRequest(new Command.SetVel(100)));
            r1.await(t -> false);
        });
        robot(r2, () -> r2.await(t -> false));
        accept("r1", "r2");

        steps(1, "r1", "r2");
        assertEquals(Map.of("r1", List.of(new Command.SetVel(100)), "r2", List.of()), requests(1));
        steps(2, "r1", "r2");
        assertEquals(Map.of("r1", List.of(), "r2", List.of()), requests(2));
        listener.setSoTimeout(300);
        assertThrows(java.net.SocketTimeoutException.class, listener::accept, "no second connection");
    }

    @Test
    void whenOneRobotIsLateTheOthersRequestsGoFirst() throws Exception {
        CountDownLatch mayYield = new CountDownLatch(1);
        r1 = hardware("r1");
        r2 = hardware("r2");
        robot(r1, () -> r1.await(t -> false));
        robot(r2, () -> {
            r2.await(t -> t >= 100);
            assertTrue(mayYield.await(WAIT_MS, TimeUnit.MILLISECONDS));
            r2.request(new RobotRequest(new Command.Stop()));
            r2.await(t -> false);
        });
        accept("r1", "r2");
        steps(1, "r1", "r2");
        requests(1);

        long sent = System.nanoTime();
        steps(2, "r1", "r2");
        assertEquals(Map.of("r1", List.of()), requests(2), "r1 alone while r2 computes");
        assertTrue(System.nanoTime() - sent >= TimeUnit.MILLISECONDS.toNanos(SharedLink.LINGER_MS),
                "after waiting " + SharedLink.LINGER_MS + " ms for r2");
        mayYield.countDown();
        assertEquals(Map.of("r2", List.of(new Command.Stop())), requests(2));
    }

    @Test
    void aByeNamingOneRobotEndsItAloneAndAByeForTheLinkEndsAll() throws Exception {
        r1 = hardware("r1");
        r2 = hardware("r2");
        robot(r1, () -> r1.await(t -> false));
        robot(r2, () -> r2.await(t -> false));
        accept("r1", "r2");
        steps(1, "r1", "r2");
        requests(1);

        out.write(new Bye("it did not send its requests in time", "r2"));
        steps(2, "r1");

        assertEquals(Map.of("r1", List.of()), requests(2));
        assertTrue(r2.isEnded());
        assertEquals(RunEnd.Kind.DROPPED, r2.runEnd().kind());
        assertEquals("it did not send its requests in time", r2.endReason());
        assertFalse(r1.isEnded());
        out.write(new Bye("done: step limit 2 reached"));
        assertEquals(null, in.read(), "the link closes");
        Await.until(Duration.ofMillis(WAIT_MS), "r1 ends with the link", r1::isEnded);
        assertEquals(RunEnd.Kind.RUN_ENDED, r1.runEnd().kind());
        assertEquals("step limit 2 reached", r1.endReason());
    }

    @Test
    void aRobotRefusedOnALinkFailsToConnectWithTheReasonAndTheOthersGoOn() throws Exception {
        r1 = hardware("r1");
        robot(r1, () -> r1.await(t -> false));
        accept("r1");
        HardwareSimulator r9 = hardware("r9");
        IOException[] failure = new IOException[1];
        CountDownLatch done = new CountDownLatch(1);
        code.start("code-r9", () -> {
            try {
                r9.connect("127.0.0.1", listener.getLocalPort());
            } catch (IOException e) {
                failure[0] = e;
            }
            done.countDown();
        });
        assertEquals("r9", assertInstanceOf(RobotHello.class, in.read()).name());
        out.write(new Bye("refused: world w has no robot named 'r9'", "r9"));

        assertTrue(done.await(WAIT_MS, TimeUnit.MILLISECONDS));
        assertTrue(failure[0].getMessage().endsWith(" refused: world w has no robot named 'r9'"), failure[0].getMessage());
        assertEquals(new RunEnd("r9", RunEnd.Kind.REFUSED, "127.0.0.1:" + listener.getLocalPort(), 0,
                "world w has no robot named 'r9'"), r9.runEnd());
        steps(1, "r1");
        assertEquals(Set.of("r1"), requests(1).keySet());
    }
}
