package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.hw.FakeLink.WAIT_MS;

import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Await;
import robosim.protocol.Command;
import robosim.protocol.RobotHello;
import robosim.protocol.SonarReading;

/**
 * The HardwareSimulator alone, over a {@link FakeLink}: its request queue, the hand-over of each
 * step to the robot's code, who sends a step's requests, and how it ends. No connection, no
 * Environment.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class HardwareSimulatorUnitTest {
    private final RobotCode code = new RobotCode();
    private final BlockingQueue<RobotSensorResponse> responses = new LinkedBlockingQueue<>();
    private final FakeLink link = new FakeLink();
    private final HardwareSimulator hw = new HardwareSimulator(new RobotHello("r1", "pioneer", TestRobot.PARAMETERS),
            responses::add, new HardwareOptions(WAIT_MS, WAIT_MS, WAIT_MS));

    @AfterEach
    void end() throws InterruptedException {
        hw.ended(RunEnd.Kind.RUN_ENDED, "the test is over");
        code.close();
    }

    private static RobotRequest req(Command c) {
        return new RobotRequest(c);
    }

    /** Connects on a robot-code thread, then runs {@code body} there. */
    private Thread robot(RobotCode.Body body) throws InterruptedException {
        CountDownLatch connected = new CountDownLatch(1);
        Thread t = code.start("code", () -> {
            hw.connect(link);
            connected.countDown();
            body.run();
        });
        assertTrue(connected.await(WAIT_MS, TimeUnit.MILLISECONDS));
        return t;
    }

    @Test
    void connectingSaysHelloOverTheLinkAndReturnsTheWelcome() throws Exception {
        robot(() -> { });
        assertEquals("r1", link.hello.name());
        assertSame(hw, link.receiver, "the link delivers steps to the simulator");
        assertFalse(hw.isEnded());
    }

    @Test
    void requestsMadeBeforeAYieldAreTheOpenStepsRequestsInOrder() throws Exception {
        CountDownLatch stepOpen = new CountDownLatch(1);
        robot(() -> {
            assertTrue(stepOpen.await(WAIT_MS, TimeUnit.MILLISECONDS));
            hw.request(req(new Command.SetVel(300)));
            hw.request(req(new Command.Say("hi")));
            hw.await(t -> t >= 100);
            hw.request(req(new Command.Stop()));
            hw.await(t -> false);
        });
        link.step(1);
        stepOpen.countDown();

        FakeLink.Sent first = link.next();
        assertEquals(1, first.step());
        assertEquals(List.of(req(new Command.SetVel(300)), req(new Command.Say("hi"))), first.requests());
        assertEquals("code", first.thread(), "the step that came while the code ran is sent by the code's yield");

        link.step(2);
        FakeLink.Sent second = link.next();
        assertEquals(new FakeLink.Sent(2, List.of(req(new Command.Stop())), "code"), second,
                "woken at time 100, the code yields again and sends step 2 itself");
    }

    @Test
    void aStepThatWakesNobodyIsAnsweredByTheLinksThreadAtOnce() throws Exception {
        Thread code = robot(() -> hw.await(t -> t >= 10_000));
        Await.until(Duration.ofMillis(WAIT_MS), "the code yields", () -> code.getState() == Thread.State.WAITING);

        for (long step = 1; step <= 2; step++) {
            link.step(step);

            FakeLink.Sent sent = link.sent.poll();
            assertEquals(new FakeLink.Sent(step, List.of(), Thread.currentThread().getName()), sent,
                    "answered before step() returned, on the thread that delivered it");
        }
    }

    @Test
    void theRobotGetsEachResponseOnlyWhileItsCodeIsYielded() throws Exception {
        CountDownLatch mayYield = new CountDownLatch(1);
        robot(() -> {
            assertTrue(mayYield.await(WAIT_MS, TimeUnit.MILLISECONDS));
            hw.await(t -> false);
        });

        link.step(1);
        assertNull(responses.poll(100, TimeUnit.MILLISECONDS), "held while the code runs");
        assertEquals(0, hw.step());
        mayYield.countDown();

        RobotSensorResponse r = responses.poll(WAIT_MS, TimeUnit.MILLISECONDS);
        assertEquals(1, r.openStep());
        assertEquals(0, r.step());
        assertArrayEquals(new int[] {1000}, r.state().get(SonarReading.PART).ranges());
        link.next();
        link.step(2);
        assertEquals(1, responses.poll(WAIT_MS, TimeUnit.MILLISECONDS).step());
        assertEquals(1, hw.step());
        assertEquals(100, hw.timeMs());
    }

    @Test
    void theEndOfTheLinkWakesTheCodeAndGivesTheReason() throws Exception {
        Thread t = robot(() -> hw.await(time -> false));
        link.step(1);
        link.next();

        hw.ended(RunEnd.Kind.RUN_ENDED, "step limit 1 reached");

        RobotCode.join(t);
        assertTrue(hw.isEnded());
        assertEquals(new RunEnd("r1", RunEnd.Kind.RUN_ENDED, "fake:1", 1, "step limit 1 reached"), hw.runEnd());
        assertEquals("step limit 1 reached", hw.endReason());
        assertTrue(link.closed);
    }

    @Test
    void disconnectSaysByeOverTheLink() throws Exception {
        RobotCode.join(robot(() -> hw.disconnect("the program is done")));
        assertEquals("the program is done", link.byes.poll(WAIT_MS, TimeUnit.MILLISECONDS));
        assertEquals(RunEnd.Kind.LEFT, hw.runEnd().kind());
        assertEquals("the program is done", hw.endReason());
        assertTrue(link.closed);
    }

    @Test
    void whenTheCodeHasEndedTheNextStepSaysByeInstead() throws Exception {
        Thread t = robot(() -> { });
        RobotCode.join(t);

        link.step(1);

        assertEquals("the robot's code has ended", link.byes.poll(WAIT_MS, TimeUnit.MILLISECONDS));
        assertTrue(link.sent.isEmpty());
        assertTrue(hw.isEnded());
    }

    @Test
    void aRefusedRobotIsNotConnectedAndSaysWhy() {
        FakeLink refusing = new FakeLink(new RefusedException("the Environment at here refused: no robot r1",
                "no robot r1"));

        IOException e = assertThrows(IOException.class, () -> hw.connect(refusing));

        assertEquals("the Environment at here refused: no robot r1", e.getMessage());
        assertTrue(hw.isEnded());
        assertEquals(new RunEnd("r1", RunEnd.Kind.REFUSED, "fake:1", 0, "no robot r1"), hw.runEnd());
    }

    @Test
    void aConnectionThatFailsBeforeTheWelcomeIsNotConnected() {
        FakeLink failing = new FakeLink(new IOException("no Environment at here:1 within 300 ms"));

        assertThrows(IOException.class, () -> hw.connect(failing));

        assertEquals(new RunEnd("r1", RunEnd.Kind.NOT_CONNECTED, "fake:1", 0, "no Environment at here:1 within 300 ms"),
                hw.runEnd());
    }
}
