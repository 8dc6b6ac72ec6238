package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import robosim.protocol.Await;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.FrameReader;
import robosim.protocol.FrameWriter;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotRequests;
import robosim.protocol.RobotState;
import robosim.protocol.TimeStep;
import robosim.protocol.Welcome;

/**
 * The hand-over of simulated time between a robot's code and its hardware thread: who wakes on
 * which step, when a step's requests may be sent, and that those requests never depend on thread
 * timing.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class StepGateTest {
    private static final long WAIT_MS = 5_000;

    private final StepGate gate = new StepGate();
    private final List<Thread> threads = new ArrayList<>();
    /** What the test's "hardware" does when the gate says a step's requests must be sent now. */
    private volatile Runnable sender = () -> { };

    /** Yields as a HardwareSimulator does: sends if the gate says so, then waits to be woken. */
    private void await(java.util.function.LongPredicate wakeWhen) throws InterruptedException {
        if (gate.yieldUntil(wakeWhen)) {
            sender.run();
        }
        gate.awaitWake();
    }

    @AfterEach
    void stopThreads() throws InterruptedException {
        gate.close();
        for (Thread t : threads) {
            t.interrupt();
            t.join(WAIT_MS);
            assertFalse(t.isAlive(), t.getName() + " has stopped");
        }
    }

    private Thread start(String name, ThrowingRunnable body) {
        Thread t = new Thread(() -> {
            try {
                body.run();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }, name);
        t.setDaemon(true);
        threads.add(t);
        t.start();
        return t;
    }

    /** Waits (bounded) until {@code t} is blocked in {@code Object.wait}. */
    private static void awaitWaiting(Thread t) {
        Await.until(Duration.ofMillis(WAIT_MS), t.getName() + " starts waiting",
                () -> t.getState() == Thread.State.WAITING || t.getState() == Thread.State.TIMED_WAITING);
    }

    @Test
    void aWaiterForTime200SleepsThroughTime100AndWakesAtTime200() throws Exception {
        CountDownLatch woke = new CountDownLatch(1);
        AtomicLong wokeAt = new AtomicLong(-1);
        Thread t = start("waiter", () -> {
            await(time -> time >= 200);
            wokeAt.set(gate.timeMs());
            woke.countDown();
        });
        awaitWaiting(t);

        gate.advance(1, 100, () -> { });
        assertFalse(woke.await(200, TimeUnit.MILLISECONDS), "time 100 does not satisfy time >= 200");

        gate.advance(2, 200, () -> { });
        assertTrue(woke.await(WAIT_MS, TimeUnit.MILLISECONDS), "time 200 wakes it");
        assertEquals(200, wokeAt.get());
    }

    @Test
    void theStepIsSentByTheLastThreadToYieldAndOnlyThen() throws Exception {
        AtomicReference<String> sentBy = new AtomicReference<>();
        CountDownLatch sent = new CountDownLatch(1);
        sender = (() -> {
            sentBy.set(Thread.currentThread().getName());
            sent.countDown();
        });
        CountDownLatch mayYield = new CountDownLatch(1);
        Thread sleeper = start("sleeps-on", () -> {
            gate.join(Thread.currentThread());
            await(time -> false);
        });
        Thread woken = start("woken-at-100", () -> {
            gate.join(Thread.currentThread());
            await(time -> time >= 100);
            assertTrue(mayYield.await(WAIT_MS, TimeUnit.MILLISECONDS));
            await(time -> false);
        });
        awaitWaiting(sleeper);
        awaitWaiting(woken);

        assertFalse(gate.advance(1, 100, () -> { }), "one participant woke: nobody sends yet");
        assertFalse(sent.await(150, TimeUnit.MILLISECONDS), "sent while a participant was still running");
        mayYield.countDown();
        assertTrue(sent.await(WAIT_MS, TimeUnit.MILLISECONDS));
        assertEquals("woken-at-100", sentBy.get());
        assertFalse(gate.claimIfYielded(), "a step is sent once");
    }

    @Test
    void aStepThatArrivesWhileCodeRunsIsHeldUntilTheCodeYields() throws Exception {
        CountDownLatch joined = new CountDownLatch(1);
        CountDownLatch mayYield = new CountDownLatch(1);
        start("still-running", () -> {
            gate.join(Thread.currentThread());
            joined.countDown();
            assertTrue(mayYield.await(WAIT_MS, TimeUnit.MILLISECONDS));
            await(time -> false);
        });
        assertTrue(joined.await(WAIT_MS, TimeUnit.MILLISECONDS));
        AtomicReference<String> state = new AtomicReference<>("old");
        CountDownLatch installed = new CountDownLatch(1);
        assertFalse(gate.advance(1, 100, () -> {
            state.set("new");
            installed.countDown();
        }), "held: nobody may send yet");
        assertFalse(installed.await(150, TimeUnit.MILLISECONDS), "the state must not change while the robot's code runs");
        assertEquals("old", state.get());
        assertEquals(0, gate.step());
        mayYield.countDown();
        assertTrue(installed.await(WAIT_MS, TimeUnit.MILLISECONDS), "installed by the thread that yielded");
        assertEquals("new", state.get());
        assertEquals(1, gate.step());
    }

    @Test
    void advanceAsksTheCallerToSendWhenNobodyWakes() throws Exception {
        CountDownLatch waiting = new CountDownLatch(1);
        Thread t = start("sleeper", () -> {
            gate.join(Thread.currentThread());
            waiting.countDown();
            await(time -> time >= 300);
        });
        assertTrue(waiting.await(WAIT_MS, TimeUnit.MILLISECONDS));
        awaitWaiting(t);
        assertTrue(gate.advance(1, 100, () -> { }), "the sleeper sleeps on: the caller sends");
        assertFalse(gate.claimIfYielded());
        assertTrue(gate.advance(2, 200, () -> { }));
    }

    @Test
    void aParticipantThatDiesIsDroppedAndTheOthersYieldsSuffice() throws Exception {
        CountDownLatch waiting = new CountDownLatch(1);
        Thread yields = start("yields", () -> {
            gate.join(Thread.currentThread());
            waiting.countDown();
            await(time -> false);
        });
        Thread dies = start("dies", () -> gate.join(Thread.currentThread()));
        assertTrue(waiting.await(WAIT_MS, TimeUnit.MILLISECONDS));
        awaitWaiting(yields);
        dies.join(WAIT_MS);
        assertFalse(dies.isAlive());

        assertTrue(gate.advance(1, 0, () -> { }), "the dead participant no longer counts");
        assertEquals(1, gate.participantCount());
    }

    @Test
    void whenEveryParticipantHasDiedNoneRemain() throws Exception {
        Thread dies = start("dies", () -> gate.join(Thread.currentThread()));
        dies.join(WAIT_MS);
        assertFalse(dies.isAlive());

        assertTrue(gate.advance(1, 0, () -> { }));
        assertEquals(0, gate.participantCount());
    }

    @Test
    void closeReleasesAWaitingThread() throws Exception {
        CountDownLatch released = new CountDownLatch(1);
        Thread t = start("waiter", () -> {
            await(time -> false);
            released.countDown();
        });
        awaitWaiting(t);
        assertFalse(gate.isClosed());

        gate.close();
        assertTrue(released.await(WAIT_MS, TimeUnit.MILLISECONDS), "close wakes the waiter");
        assertTrue(gate.isClosed());
    }

    @Test
    void theUpdateRunsBeforeTheWaitersWake() throws Exception {
        AtomicReference<String> state = new AtomicReference<>("old");
        AtomicReference<String> seen = new AtomicReference<>();
        AtomicLong seenStep = new AtomicLong(-1);
        CountDownLatch woke = new CountDownLatch(1);
        Thread t = start("waiter", () -> {
            await(time -> time >= 100);
            seen.set(state.get());
            seenStep.set(gate.step());
            woke.countDown();
        });
        awaitWaiting(t);

        gate.advance(1, 100, () -> {
            try {
                // a slow update: it waits for a waiter woken early, who would see "old"
                woke.await(100, TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            state.set("new");
        });
        assertTrue(woke.await(WAIT_MS, TimeUnit.MILLISECONDS));
        assertEquals("new", seen.get());
        assertEquals(1, seenStep.get());
    }

    /**
     * A robot thread that makes batch k of requests after waking at simulated time k × 100 ms must
     * see batch k sent as its requests for step k + 1 (the step whose TimeStep carried time k × 100),
     * in order, however long it dawdles between requests and before it yields.
     */
    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3})
    void eachStepCarriesExactlyTheRequestsMadeBeforeTheYieldWhateverTheJitter(long seed) throws Exception {
        final int steps = 12;
        Random jitter = new Random(seed);
        MessageCodec codec = new MessageCodec();
        try (ServerSocket listener = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            listener.setSoTimeout((int) WAIT_MS);
            HardwareSimulator hw = new HardwareSimulator(new RobotHello("r1", "pioneer", null),
                    r -> { }, new HardwareOptions(WAIT_MS, 10_000, 5_000));
            AtomicReference<Throwable> robotFailure = new AtomicReference<>();
            Thread robot = start("robot-r1", () -> {
                try {
                    hw.connect("127.0.0.1", listener.getLocalPort());
                    for (int k = 0; !hw.isEnded(); k++) {
                        // the dawdling is the point: requests must not depend on the code's timing
                        for (Command c : batch(k)) {
                            Thread.sleep(jitter.nextInt(12));
                            hw.request(new RobotRequest(c));
                        }
                        Thread.sleep(jitter.nextInt(12));
                        long wake = (k + 1) * 100L;
                        hw.await(time -> time >= wake);
                    }
                } catch (Throwable e) {
                    robotFailure.set(e);
                }
            });

            try (Socket env = listener.accept()) {
                env.setSoTimeout((int) WAIT_MS);
                FrameReader in = new FrameReader(env.getInputStream(), codec, FrameReader.DEFAULT_MAX_FRAME);
                FrameWriter out = new FrameWriter(env.getOutputStream(), codec);
                assertInstanceOf(RobotHello.class, in.read());
                out.write(new Welcome("r1", 100, state(0)));
                for (int n = 1; n <= steps; n++) {
                    out.write(new TimeStep(n, (n - 1) * 100L, state(n - 1)));
                    Message m = in.read();
                    RobotRequests requests = assertInstanceOf(RobotRequests.class, m, "step " + n);
                    assertEquals(n, requests.step());
                    assertEquals(batch(n - 1), requests.commands(), "the requests for step " + n);
                }
                out.write(new Bye("done"));
            }
            robot.join(WAIT_MS);
            assertFalse(robot.isAlive(), "the robot's code returns once the connection ends");
            assertEquals(null, robotFailure.get());
        }
    }

    /** Batch k: k % 4 requests (so some steps have none), each naming its batch and place. */
    private static List<Command> batch(int k) {
        List<Command> commands = new ArrayList<>();
        for (int i = 0; i < k % 4; i++) {
            commands.add(new Command.SetVel(k * 1000 + i));
        }
        return commands;
    }

    private static RobotState state(long step) {
        return new RobotState(step, step * 100, 0, 0, 0, 0, 0, 0, 0, false, 0);
    }

    @FunctionalInterface
    private interface ThrowingRunnable {
        void run() throws Exception;
    }
}
