package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.hw.FakeEnvironment.WAIT_MS;

import java.io.IOException;
import java.net.BindException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Await;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotRequests;
import robosim.protocol.KeepAlive;
import robosim.protocol.TimeStep;
import robosim.protocol.Welcome;
import robosim.protocol.RobotParameters;

/**
 * A robot's link to the Environment, against an Environment played by the test over loopback TCP:
 * connecting, each step's requests, and every way the link ends. (The JVM-wide watchdog may send a
 * step's requests instead of the robot's threads; the Environment sees the same frames either way.)
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class HardwareSimulatorTest {
    private static final RobotParameters PARAMETERS = TestRobot.PARAMETERS;
    private static final HardwareOptions OPTIONS = new HardwareOptions(WAIT_MS, WAIT_MS, WAIT_MS);

    /** The simulator the test made last. */
    private HardwareSimulator made;
    private final BlockingQueue<RobotSensorResponse> responses = new LinkedBlockingQueue<>();
    private final RobotCode code = new RobotCode();
    /** The thread {@link #connecting} connects on. */
    private Thread connector;
    private FakeEnvironment env;

    @BeforeEach
    void listen() throws IOException {
        env = new FakeEnvironment();
    }

    @AfterEach
    void endRun() throws Exception {
        try {
            env.close();
        } finally {
            if (made != null) {
                made.ended(RunEnd.Kind.RUN_ENDED, "the test is over");
            }
            code.close();
        }
    }

    private HardwareSimulator hardware(String name, HardwareOptions options) {
        made = new HardwareSimulator(new RobotHello(name, "pioneer", PARAMETERS), responses::add, options);
        return made;
    }

    /**
     * Runs robot code on a thread of its own: it connects (and so becomes the robot's code), then
     * runs {@code body}.
     */
    private Thread run(HardwareSimulator hw, RobotCode.Body body) {
        return code.start("code", () -> {
            hw.connect("127.0.0.1", env.port());
            body.run();
        });
    }

    /** Yields until the link ends. */
    private void yieldUntilTheEnd() throws InterruptedException {
        made.await(time -> false);
    }

    /** Connects on a thread of its own, for tests of a connect that fails. */
    private CompletableFuture<Welcome> connecting(HardwareSimulator hw, int port) {
        CompletableFuture<Welcome> welcome = new CompletableFuture<>();
        connector = code.start("connecting", () -> {
            try {
                welcome.complete(hw.connect("127.0.0.1", port));
            } catch (Throwable e) {
                welcome.completeExceptionally(e);
            }
        });
        return welcome;
    }

    private static Throwable failureOf(CompletableFuture<?> f) {
        ExecutionException e = assertThrows(ExecutionException.class, () -> f.get(WAIT_MS, TimeUnit.MILLISECONDS));
        return e.getCause();
    }

    // ---- connecting ----

    @Test
    void theHelloCarriesTheRobotsNameTypeAndParametersAndTheWelcomeIsReturned() throws Exception {
        HardwareSimulator hw = hardware("r1", OPTIONS);
        CompletableFuture<Welcome> welcome = connecting(hw, env.port());
        assertEquals(new RobotHello("r1", "pioneer", PARAMETERS), env.acceptHello());
        env.send(new Welcome("r1", 250, FakeEnvironment.state(0)));
        Welcome w = welcome.get(WAIT_MS, TimeUnit.MILLISECONDS);
        assertEquals("r1", w.name());
        assertEquals(250, w.stepMs());
        assertEquals(0, w.state().step());
        hw.disconnect("the test is over");
        assertEquals(new Bye("the test is over"), env.read());
    }

    @Test
    void anEnvironmentThatRefusesTheRobotFailsTheConnectWithItsReason() throws Exception {
        CompletableFuture<Welcome> welcome = connecting(hardware("r9", OPTIONS), env.port());
        env.acceptHello();
        env.send(new Bye("refused: world w has no robot named 'r9'"));
        Throwable e = assertInstanceOf(IOException.class, failureOf(welcome));
        assertEquals("the Environment at 127.0.0.1:" + env.port() + " refused: world w has no robot named 'r9'",
                e.getMessage());
        assertNull(env.read(), "the robot has closed its end");
        assertEquals(new RunEnd("r9", RunEnd.Kind.REFUSED, "127.0.0.1:" + env.port(), 0,
                "world w has no robot named 'r9'"), made.runEnd());
    }

    @Test
    void anEnvironmentThatAnswersTheHelloWithAStepFailsTheConnect() throws Exception {
        CompletableFuture<Welcome> welcome = connecting(hardware("r1", OPTIONS), env.port());
        env.acceptHello();
        env.send(new TimeStep(1, 0, FakeEnvironment.state(0)));
        Throwable e = assertInstanceOf(IOException.class, failureOf(welcome));
        assertEquals("the Environment at 127.0.0.1:" + env.port() + " answered an unexpected TimeStep", e.getMessage());
    }

    @Test
    void anEnvironmentThatClosesWithoutAnsweringFailsTheConnect() throws Exception {
        CompletableFuture<Welcome> welcome = connecting(hardware("r1", OPTIONS), env.port());
        env.acceptHello();
        env.closeConnection();
        Throwable e = assertInstanceOf(IOException.class, failureOf(welcome));
        assertEquals("the Environment at 127.0.0.1:" + env.port() + " answered nothing (the connection closed)",
                e.getMessage());
    }

    @Test
    void anEnvironmentThatNeverWelcomesTheRobotTimesTheConnectOut() throws Exception {
        CompletableFuture<Welcome> welcome = connecting(hardware("r1", new HardwareOptions(300, WAIT_MS, WAIT_MS)),
                env.port());
        env.acceptHello();
        assertInstanceOf(SocketTimeoutException.class, failureOf(welcome));
        assertNull(env.read(), "the robot has closed its end");
    }

    @Test
    void connectingWhereNothingListensRetriesThenFailsAtTheConnectTimeout() throws Exception {
        int port = FakeEnvironment.closedPort();
        HardwareSimulator hw = hardware("r1", new HardwareOptions(600, WAIT_MS, WAIT_MS));
        long start = System.nanoTime();
        ConnectException e = assertThrows(ConnectException.class, () -> hw.connect("127.0.0.1", port));
        long tookMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
        assertTrue(e.getMessage().startsWith("no Environment at 127.0.0.1:" + port + " within 600 ms ("),
                e.getMessage());
        assertTrue(tookMs >= 400, "it tries again every 200 ms while that fits in 600 ms; gave up after " + tookMs);
        assertTrue(tookMs < WAIT_MS, "gave up after " + tookMs + " ms");
    }

    @Test
    void aRobotStartedBeforeTheEnvironmentConnectsOnceItListens() throws Exception {
        int port = FakeEnvironment.closedPort();
        HardwareSimulator hw = hardware("r1", OPTIONS);
        CompletableFuture<Welcome> welcome = connecting(hw, port);
        Await.until(Duration.ofMillis(WAIT_MS), "the robot found nobody and waits to try again",
                () -> waitsToRetry(connector));
        try (ServerSocket late = new ServerSocket()) {
            late.setReuseAddress(true);
            try {
                late.bind(new InetSocketAddress(FakeEnvironment.loopback(), port), 1);
            } catch (BindException taken) {
                Assumptions.abort("port " + port + " was taken meanwhile");
            }
            late.setSoTimeout(WAIT_MS);
            try (Socket peer = late.accept()) {
                peer.setSoTimeout(WAIT_MS);
                MessageCodec codec = new MessageCodec();
                FrameReader in = new FrameReader(peer.getInputStream(), codec, FrameReader.DEFAULT_MAX_FRAME);
                assertEquals("r1", assertInstanceOf(RobotHello.class, in.read()).name());
                new FrameWriter(peer.getOutputStream(), codec).write(new Welcome("r1", 100, FakeEnvironment.state(0)));
                assertEquals("r1", welcome.get(WAIT_MS, TimeUnit.MILLISECONDS).name());
                hw.disconnect("the test is over");
                assertEquals(new Bye("the test is over"), in.read());
            }
        }
    }

    /** @return whether the thread is pausing between two connect attempts: it found nobody listening */
    private static boolean waitsToRetry(Thread t) {
        return t.getState() == Thread.State.TIMED_WAITING
                && Arrays.stream(t.getStackTrace()).anyMatch(f -> f.getMethodName().equals("connectSocket"));
    }

    // ---- each step's requests ----

    @Test
    void requestsMadeBetweenTwoYieldsAreSentTogetherForTheOpenStepInOrder() throws Exception {
        HardwareSimulator hw = hardware("r1", OPTIONS);
        run(hw, () -> {
            hw.request(new RobotRequest(new Command.SetVel(300)));
            hw.request(new RobotRequest(new Command.SetRotVel(-15)));
            hw.request(new RobotRequest(new Command.Say("first")));
            hw.await(time -> time >= 100);
            hw.request(new RobotRequest(new Command.Stop()));
            yieldUntilTheEnd();
        });
        env.acceptHello();
        env.welcome("r1");
        assertEquals(List.of(new Command.SetVel(300), new Command.SetRotVel(-15), new Command.Say("first")),
                env.step(1));
        assertEquals(List.of(new Command.Stop()), env.step(2));
        assertEquals(List.of(), env.step(3));
    }

    @Test
    void aStepInWhichNothingWasRequestedIsAnsweredWithAnEmptyList() throws Exception {
        HardwareSimulator hw = hardware("r1", OPTIONS);
        run(hw, this::yieldUntilTheEnd);
        env.acceptHello();
        env.welcome("r1");
        assertEquals(List.of(), env.step(1));
        assertEquals(List.of(), env.step(2));
    }

    @Test
    void aStepThatArrivesWhileTheCodeRunsIsAnsweredWithEverythingRequestedUntilItYields() throws Exception {
        HardwareSimulator hw = hardware("r1", OPTIONS);
        CountDownLatch mayYield = new CountDownLatch(1);
        run(hw, () -> {
            hw.request(new RobotRequest(new Command.Say("before step 1 arrived")));
            assertTrue(mayYield.await(WAIT_MS, TimeUnit.MILLISECONDS));
            hw.request(new RobotRequest(new Command.Say("after step 1 arrived")));
            yieldUntilTheEnd();
        });
        env.acceptHello();
        env.welcome("r1");
        env.send(new TimeStep(1, 0, FakeEnvironment.state(0)));
        env.assertSilentFor(200);
        mayYield.countDown();
        RobotRequests r = assertInstanceOf(RobotRequests.class, env.read());
        assertEquals(1, r.step());
        assertEquals(List.of(new Command.Say("before step 1 arrived"), new Command.Say("after step 1 arrived")),
                r.commands());
    }

    @Test
    void eachStepsStateIsHandedToTheRobotAsAResponse() throws Exception {
        HardwareSimulator hw = hardware("r1", OPTIONS);
        run(hw, this::yieldUntilTheEnd);
        env.acceptHello();
        env.welcome("r1");
        env.step(1);
        env.step(2);
        assertEquals(0, responses.poll(WAIT_MS, TimeUnit.MILLISECONDS).step());
        RobotSensorResponse second = responses.poll(WAIT_MS, TimeUnit.MILLISECONDS);
        assertEquals(1, second.step());
        assertEquals(100, second.timeMs());
        assertEquals(1, made.step());
        assertEquals(100, made.timeMs());
    }

    // ---- how the link ends ----

    @Test
    void aByeFromTheEnvironmentEndsTheLinkWithItsReason() throws Exception {
        HardwareSimulator hw = hardware("r1", OPTIONS);
        Thread robot = run(hw, this::yieldUntilTheEnd);
        env.acceptHello();
        env.welcome("r1");
        env.step(1);
        assertNull(hw.endReason(), "connected");
        env.send(new Bye("done: step limit 1 reached"));
        RobotCode.join(robot);
        assertEquals(new RunEnd("r1", RunEnd.Kind.RUN_ENDED, "127.0.0.1:" + env.port(), 1, "step limit 1 reached"),
                hw.runEnd());
        assertTrue(made.isEnded());
        assertNull(env.read(), "the robot has closed its end");
    }

    @Test
    void anEnvironmentThatClosesTheConnectionEndsTheLink() throws Exception {
        HardwareSimulator hw = hardware("r1", OPTIONS);
        Thread robot = run(hw, this::yieldUntilTheEnd);
        env.acceptHello();
        env.welcome("r1");
        env.step(1);
        env.closeConnection();
        RobotCode.join(robot);
        assertEquals(new RunEnd("r1", RunEnd.Kind.LOST, "127.0.0.1:" + env.port(), 1,
                "it closed the connection without a bye"), hw.runEnd());
        assertEquals("robot r1 lost the Environment at 127.0.0.1:" + env.port()
                + " after step 1: it closed the connection without a bye", hw.runEnd().describe());
    }

    @Test
    void anUnexpectedMessageInTheRunEndsTheLinkNamingIt() throws Exception {
        HardwareSimulator hw = hardware("r1", OPTIONS);
        Thread robot = run(hw, this::yieldUntilTheEnd);
        env.acceptHello();
        env.welcome("r1");
        env.step(1);
        env.welcome("r1");
        RobotCode.join(robot);
        assertEquals(RunEnd.Kind.LOST, hw.runEnd().kind());
        assertEquals("it sent an unexpected Welcome", hw.endReason());
        assertNull(env.read(), "the robot has closed its end");
    }

    @Test
    void anEnvironmentSilentForTheLostTimeIsDeclaredLost() throws Exception {
        HardwareSimulator hw = hardware("r1", new HardwareOptions(WAIT_MS, 300, WAIT_MS));
        Thread robot = run(hw, this::yieldUntilTheEnd);
        env.acceptHello();
        env.welcome("r1");
        env.step(1);
        RobotCode.join(robot);
        assertEquals(new RunEnd("r1", RunEnd.Kind.LOST, "127.0.0.1:" + env.port(), 1,
                "it sent nothing, neither a step nor a keep-alive, for 300 ms"), hw.runEnd());
        assertNull(env.read(), "the robot has closed its end");
    }

    @Test
    void keepAlivesKeepAPausedEnvironmentFromBeingDeclaredLost() throws Exception {
        HardwareSimulator hw = hardware("r1", new HardwareOptions(WAIT_MS, 2_000, WAIT_MS));
        Thread robot = run(hw, this::yieldUntilTheEnd);
        env.acceptHello();
        env.welcome("r1");
        env.step(1);
        // 3 s without a step, a keep-alive every 200 ms: longer than the lost time, never silent for it
        for (int i = 0; i < 15; i++) {
            env.send(new KeepAlive(1));
            env.assertSilentFor(200);
        }
        assertNull(hw.runEnd(), "still in the run");
        assertEquals(List.of(), env.step(2));
        env.send(new Bye("done: step limit 2 reached"));
        RobotCode.join(robot);
        assertEquals(RunEnd.Kind.RUN_ENDED, hw.runEnd().kind());
    }

    @Test
    void aByeThatNamesNoRunEndDropsTheRobotWithTheEnvironmentsReason() throws Exception {
        HardwareSimulator hw = hardware("r1", OPTIONS);
        Thread robot = run(hw, this::yieldUntilTheEnd);
        env.acceptHello();
        env.welcome("r1");
        env.step(1);
        env.send(new Bye("it did not send its requests for step 2 within 500 ms"));
        RobotCode.join(robot);
        assertEquals(new RunEnd("r1", RunEnd.Kind.DROPPED, "127.0.0.1:" + env.port(), 1,
                "it did not send its requests for step 2 within 500 ms"), hw.runEnd());
    }

    @Test
    void disconnectSaysByeWithTheReasonAndEndsTheLink() throws Exception {
        HardwareSimulator hw = hardware("r1", OPTIONS);
        Thread robot = run(hw, () -> {
            hw.await(time -> time >= 100);
            hw.disconnect("the program is done");
        });
        env.acceptHello();
        env.welcome("r1");
        assertEquals(List.of(), env.step(1));
        env.send(new TimeStep(2, 100, FakeEnvironment.state(1)));
        assertEquals(new Bye("the program is done"), env.read());
        RobotCode.join(robot);
        assertEquals(RunEnd.Kind.LEFT, hw.runEnd().kind());
        assertEquals("the program is done", hw.endReason());
        assertTrue(made.isEnded());
    }

    @Test
    void aRobotWhoseCodeHasEndedSaysByeAtTheNextStep() throws Exception {
        HardwareSimulator hw = hardware("r1", OPTIONS);
        Thread robot = run(hw, () -> { });
        env.acceptHello();
        env.welcome("r1");
        RobotCode.join(robot);
        env.send(new TimeStep(1, 0, FakeEnvironment.state(0)));
        assertEquals(new Bye("the robot's code has ended"), env.read());
        assertNull(env.read(), "the robot has closed its end");
        assertEquals("the robot's code has ended", hw.endReason());
    }

    @Test
    void aRobotKeptAliveAnswersStepsAfterItsCodeHasEndedUntilTheRunEnds() throws Exception {
        HardwareSimulator hw = hardware("r-kept", OPTIONS);
        Thread robot = run(hw, () -> hw.keepAlive(true));
        env.acceptHello();
        env.welcome("r-kept");
        RobotCode.join(robot);
        assertEquals(List.of(), env.step(1));
        assertEquals(List.of(), env.step(2));
        env.send(new Bye("done: step limit 2 reached"));
        assertNull(env.read(), "the robot has closed its end");
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.getName().equals("hw-keep-r-kept")) {
                RobotCode.join(t);
            }
        }
        assertEquals("step limit 2 reached", hw.endReason());
    }

    @Test
    void codeThatDoesNotYieldIsWarnedAboutOncePerStep() throws Exception {
        BlockingQueue<String> warnings = new LinkedBlockingQueue<>();
        Handler handler = new Handler() {
            @Override
            public void publish(LogRecord r) {
                if (r.getLevel() == Level.WARNING && r.getMessage().startsWith("robot r-slow's")) {
                    warnings.add(r.getMessage());
                }
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        Logger log = Logger.getLogger(HardwareSimulator.class.getName());
        log.addHandler(handler);
        log.setUseParentHandlers(false); // the warning is expected: keep it off the console
        try {
            HardwareSimulator hw = hardware("r-slow", new HardwareOptions(WAIT_MS, WAIT_MS, 100));
            CountDownLatch mayYield = new CountDownLatch(1);
            run(hw, () -> {
                assertTrue(mayYield.await(WAIT_MS, TimeUnit.MILLISECONDS));
                hw.request(new RobotRequest(new Command.Say("at last")));
                yieldUntilTheEnd();
            });
            env.acceptHello();
            env.welcome("r-slow");
            env.send(new TimeStep(1, 0, FakeEnvironment.state(0)));
            assertEquals("robot r-slow's code has not yielded for step 1 after 100 ms; it should wait with"
                    + " ArUtil.sleep or a blocking call", warnings.poll(WAIT_MS, TimeUnit.MILLISECONDS));
            assertNull(warnings.poll(300, TimeUnit.MILLISECONDS), "one warning for step 1");
            mayYield.countDown();
            RobotRequests r = assertInstanceOf(RobotRequests.class, env.read());
            assertEquals(1, r.step());
            assertEquals(List.of(new Command.Say("at last")), r.commands());
        } finally {
            log.setUseParentHandlers(true);
            log.removeHandler(handler);
        }
    }
}
