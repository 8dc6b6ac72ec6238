package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static robosim.hw.FakeLink.WAIT_MS;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Bye;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.LinkHello;
import robosim.protocol.LinkRequests;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotHello;
import robosim.protocol.TimeSteps;
import robosim.protocol.Welcome;

/**
 * The runtime the robots of a program share: it opens with its first robot and closes, its threads
 * gone, when its last leaves; two runtimes in one JVM keep their links and clocks apart; robots given
 * none share the default runtime, made fresh after its last robot left.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class RobotRuntimeTest {
    private static final HardwareOptions OPTIONS = new HardwareOptions(WAIT_MS, WAIT_MS, 60_000);
    /** Platform threads, which a test can find by name on any JDK. */
    private static final RuntimeChoices SHARED = RuntimeChoices.defaults().withLinks(EnvironmentLinks.Mode.SHARED)
            .withVirtualThreads(false);
    private final MessageCodec codec = new MessageCodec();
    private final RobotCode code = new RobotCode();
    private ServerSocket listener;

    @AfterEach
    void close() throws Exception {
        try {
            if (listener != null) {
                listener.close();
            }
        } finally {
            code.close();
        }
    }

    private static HardwareSimulator hardware(String name, RobotRuntime runtime) {
        return new HardwareSimulator(new RobotHello(name, "pioneer", TestRobot.PARAMETERS), r -> { }, OPTIONS, runtime);
    }

    private static boolean running(String threadName) {
        return Thread.getAllStackTraces().keySet().stream().anyMatch(t -> t.getName().equals(threadName) && t.isAlive());
    }

    private static void awaitGone(String threadName) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
        while (running(threadName)) {
            assertTrue(System.nanoTime() < deadline, threadName + " still runs after " + WAIT_MS + " ms");
            Thread.sleep(5);
        }
    }

    @Test
    void aRuntimeOpensWithItsFirstRobotAndClosesWithItsThreadsWhenItsLastLeaves() throws Exception {
        RobotRuntime runtime = RobotRuntime.create("closing", RuntimeChoices.defaults());
        assertFalse(runtime.isOpen());
        assertFalse(running("hw-watchdog-closing"), "no thread before its first robot");
        HardwareSimulator r1 = hardware("r1", runtime);
        HardwareSimulator r2 = hardware("r2", runtime);
        r1.connect(new FakeLink());
        r2.connect(new FakeLink());
        assertEquals(2, runtime.robots());
        assertTrue(running("hw-watchdog-closing"));

        r1.disconnect("the test is over for r1");
        assertTrue(runtime.isOpen(), "r2 still uses it");
        assertTrue(running("hw-watchdog-closing"));
        r2.ended(RunEnd.Kind.RUN_ENDED, "the test is over");
        assertFalse(runtime.isOpen());
        awaitGone("hw-watchdog-closing");

        // a runtime the program made opens again for the next robot given it
        HardwareSimulator r3 = hardware("r3", runtime);
        r3.connect(new FakeLink());
        assertTrue(runtime.isOpen());
        assertTrue(running("hw-watchdog-closing"));
        r3.ended(RunEnd.Kind.RUN_ENDED, "the test is over");
        awaitGone("hw-watchdog-closing");
    }

    @Test
    void twoRuntimesInOneJvmHaveLinksAndClocksOfTheirOwn() throws Exception {
        listener = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
        listener.setSoTimeout((int) WAIT_MS);
        RobotRuntime teamA = RobotRuntime.create("team-a", SHARED);
        RobotRuntime teamB = RobotRuntime.create("team-b", SHARED);
        TestRobot a1 = robot("a1", teamA);
        robot("b1", teamB);
        Map<String, Link> links = new HashMap<>();
        for (int i = 0; i < 2; i++) {
            Link l = new Link(listener.accept());
            links.put(l.robot, l);
        }
        Link a = links.get("a1");
        Link b = links.get("b1");
        String readerA = "hw-link-team-a-127.0.0.1:" + listener.getLocalPort();
        String readerB = "hw-link-team-b-127.0.0.1:" + listener.getLocalPort();
        assertTrue(running(readerA) && running(readerB), "a shared link for each runtime");
        for (long step = 1; step <= 2; step++) {
            a.step(step);
        }
        for (long step = 1; step <= 4; step++) {
            b.step(step);
        }
        assertEquals(100, teamA.latestTimeMs());
        assertEquals(300, teamB.latestTimeMs());
        assertSame(teamA, a1.getRuntime());

        a1.disconnect();
        assertEquals(new Bye("the robot's program disconnected", "a1"), a.in.read());
        assertNull(a.in.read(), "team a's last robot left: its link closes");
        assertFalse(teamA.isOpen());
        awaitGone("hw-watchdog-team-a");
        awaitGone(readerA);
        b.step(5);
        assertTrue(teamB.isOpen(), "team b goes on");
        assertTrue(running("hw-watchdog-team-b") && running(readerB));
        b.out.write(new Bye("done: step limit 5 reached"));
        awaitGone("hw-watchdog-team-b");
    }

    /** A robot of a runtime whose code waits in simulated time until its part ends. */
    private TestRobot robot(String name, RobotRuntime runtime) {
        TestRobot robot = new TestRobot(name, listener.getLocalPort());
        robot.setRuntime(runtime);
        code.start("code-" + name, () -> {
            robot.connect(OPTIONS);
            while (robot.isConnected()) {
                robot.sleepSimulated(100);
            }
        });
        return robot;
    }

    /** The Environment's side of one shared link with one robot, welcomed. */
    private final class Link {
        final FrameReader in;
        final FrameWriter out;
        final String robot;

        Link(Socket s) throws IOException {
            s.setSoTimeout((int) WAIT_MS);
            in = new FrameReader(s.getInputStream(), codec, FrameReader.DEFAULT_MAX_FRAME);
            out = new FrameWriter(s.getOutputStream(), codec);
            assertInstanceOf(LinkHello.class, in.read());
            robot = assertInstanceOf(RobotHello.class, in.read()).name();
            out.write(new Welcome(robot, 100, FakeLink.state(0)));
        }

        /** Opens a step for the robot and reads its answer. */
        void step(long step) throws IOException {
            out.write(new TimeSteps(step, (step - 1) * 100, List.of(new TimeSteps.ForRobot(robot,
                    FakeLink.state(step - 1)))));
            LinkRequests r = assertInstanceOf(LinkRequests.class, in.read());
            assertEquals(step, r.step());
        }
    }

    @Test
    void robotsGivenNoRuntimeShareTheDefaultOneMadeFreshAfterItsLastRobotLeft() throws Exception {
        assumeFalse(RobotRuntime.defaultRuntime().isOpen(), "no robot of an earlier test is in the default runtime");
        try (RunEndWatch watch = RunEndWatch.open()) {
            HardwareSimulator r1 = hardware("r1", null);
            r1.connect(new FakeLink());
            RobotRuntime first = r1.runtime();
            assertTrue(first.isDefault() && first.isOpen());
            r1.disconnect("the test is over for r1");
            assertFalse(first.isOpen());

            HardwareSimulator r2 = hardware("r2", null);
            r2.connect(new FakeLink());
            assertNotSame(first, r2.runtime(), "a fresh default runtime");
            assertSame(r2.runtime(), RobotRuntime.currentDefault().orElseThrow());
            assertFalse(first.isOpen());
            r2.ended(RunEnd.Kind.RUN_ENDED, "the test is over");
            assertEquals(List.of("r1", "r2"), watch.ends().stream().map(RunEnd::robot).toList(),
                    "a watch of the default runtime follows the fresh one's robots too");
        }
    }

    @Test
    void aRuntimesNameIsCheckedAndAConnectedRobotKeepsItsRuntime() throws Exception {
        assertThrows(IllegalArgumentException.class, () -> RobotRuntime.create("no spaces", SHARED));
        assertThrows(IllegalArgumentException.class, () -> RobotRuntime.create("", SHARED));
        RobotRuntime runtime = RobotRuntime.create("kept", RuntimeChoices.defaults());
        TestRobot robot = new TestRobot("r1", 1);
        robot.setRuntime(runtime);
        FakeLink link = new FakeLink();
        // connected on a code thread: the connecting thread becomes the robot's
        RobotCode.join(code.start("code-r1", () -> robot.connect(OPTIONS, link)));
        try {
            assertThrows(IllegalStateException.class, () -> robot.setRuntime(null));
            assertSame(runtime, robot.getRuntime());
            assertEquals(1, runtime.robots());
        } finally {
            link.receiver.ended(RunEnd.Kind.RUN_ENDED, "the test is over");
        }
        assertFalse(runtime.isOpen());
    }
}
