package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.hw.FakeEnvironment.WAIT_MS;

import java.io.IOException;
import java.net.ConnectException;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import robosim.protocol.Bye;
import robosim.protocol.CapturedLog;
import robosim.protocol.Command;
import robosim.protocol.Command.Addressing;
import robosim.protocol.MessageDelivery;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotState;
import robosim.protocol.RobotStates;
import robosim.protocol.SonarReading;
import robosim.protocol.TimeStep;
import robosim.protocol.Welcome;

/**
 * What every Robot-Object shares, run against an Environment played by the test over loopback
 * TCP: its hello and welcome, the state it holds after each step, waiting in simulated time, and
 * messages out and in.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class AbstractRobotTest {
    private static final HardwareOptions OPTIONS = new HardwareOptions(WAIT_MS, WAIT_MS, WAIT_MS);

    /** A payload sent as JSON. */
    record Greeting(String from, int count) {
    }

    private final RobotCode code = new RobotCode();
    /** What the robot's code saw, in order. */
    private final BlockingQueue<Object> seen = new LinkedBlockingQueue<>();
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
            code.close();
        }
    }

    /**
     * Runs a robot's code on a thread of its own: it connects, runs {@code body}, then yields until
     * the robot is disconnected.
     */
    private Thread run(TestRobot robot, RobotCode.Body body) {
        return code.start("code-" + robot.getName(), () -> {
            robot.connect(OPTIONS);
            body.run();
            while (robot.isConnected()) {
                robot.sleepSimulated(1_000);
            }
        });
    }

    /** Accepts the robot and welcomes it with 100 ms steps. */
    private void welcome(String name) throws IOException {
        env.acceptHello();
        env.welcome(name);
    }

    private Object nextSeen() throws InterruptedException {
        Object o = seen.poll(WAIT_MS, TimeUnit.MILLISECONDS);
        assertTrue(o != null, "the robot's code saw nothing within " + WAIT_MS + " ms");
        return o;
    }

    private static RobotState withMessages(long step, List<MessageDelivery> messages, List<String> errors) {
        return RobotStates.of(step, step * FakeEnvironment.STEP_MS, 0, 0, 0, 0, 0, 0, 0, false, new int[0], 0,
                new int[0], null, messages, errors, 0);
    }

    // ---- before connecting ----

    @ParameterizedTest
    @ValueSource(ints = {0, -1, 65536})
    void aPortOutside1To65535IsRefused(int port) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new TestRobot("r1", port));
        assertEquals(port + " was supplied for port: a port is 1 to 65535", e.getMessage());
    }

    @Test
    void aNewRobotKeepsItsNameHostPortAndParametersAndIsNotConnected() {
        TestRobot robot = new TestRobot("r1", 65535);
        assertEquals("r1", robot.getName());
        assertEquals("127.0.0.1", robot.getHost());
        assertEquals(65535, robot.getPort());
        assertSame(TestRobot.PARAMETERS, robot.getParameters());
        assertFalse(robot.isConnected());
        assertEquals(100, robot.getStepMs());
        assertEquals(0, robot.getStep());
        assertNull(robot.poll());
    }

    @Test
    void aPayloadJacksonCannotWriteIsRefusedWhenSent() {
        TestRobot robot = new TestRobot("r1", 5000);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> robot.broadcast(new Object()));
        assertTrue(e.getMessage().startsWith("a java.lang.Object cannot be sent: Jackson cannot write it: "),
                e.getMessage());
    }

    @Test
    void connectingWhereNothingListensFailsAfterTheConnectTimeout() throws IOException {
        TestRobot robot = new TestRobot("r1", FakeEnvironment.closedPort());
        ConnectException e = assertThrows(ConnectException.class,
                () -> robot.connect(new HardwareOptions(300, WAIT_MS, WAIT_MS)));
        assertTrue(e.getMessage().startsWith("no Environment at 127.0.0.1:" + robot.getPort() + " within 300 ms"),
                e.getMessage());
        assertNull(AbstractRobot.current(), "a robot that failed to connect is nobody's");
    }

    // ---- hello and welcome ----

    @Test
    void theHelloCarriesTheRobotsNameTypeAndParameters() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> { });
        assertEquals(new RobotHello("r1", "pioneer", TestRobot.PARAMETERS), env.acceptHello());
        env.welcome("r1");
    }

    @Test
    void theWelcomeGivesTheStepLengthAndTheStateBeforeTheFirstStep() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> seen.add("step " + robot.getStep() + " of " + robot.getStepMs() + " ms at ("
                + robot.state().x() + ", " + robot.state().y() + ", " + robot.state().th() + "), welcomed at ("
                + robot.welcomedWith.x() + ", " + robot.welcomedWith.y() + "), connected " + robot.isConnected()));
        env.acceptHello();
        env.send(new Welcome("r1", 250, new RobotState(0, 0, 1500, -750, 90, 0, 0, 0, 0, false, 0)));
        assertEquals("step 0 of 250 ms at (1500.0, -750.0, 90.0), welcomed at (1500.0, -750.0), connected true",
                nextSeen());
    }

    @Test
    void theWelcomeGivesTheWorldsPropertiesAndTheRunsSeed() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> seen.add("cellSize " + robot.getWorldProperty("cellSize") + " = "
                + robot.getWorldProperty("cellSize", 0) + ", goal " + robot.getWorldProperty("goal") + ", absent "
                + robot.getWorldProperty("absent") + " or " + robot.getWorldProperty("absent", 7.5) + " or "
                + robot.getWorldNumber("absent") + ", all " + robot.getWorldProperties() + ", seed "
                + robot.getRunSeed()));
        env.acceptHello();
        Map<String, String> properties = new LinkedHashMap<>();
        properties.put("cellSize", " 1500 ");
        properties.put("goal", "gold");
        env.send(new Welcome("r1", 100, FakeEnvironment.state(0), properties, -42));

        assertEquals("cellSize  1500  = 1500.0, goal gold, absent null or 7.5 or OptionalDouble.empty, all "
                + "{cellSize= 1500 , goal=gold}, seed -42", nextSeen());
    }

    @ParameterizedTest
    @ValueSource(strings = {"gold", "", "NaN", "Infinity", "0x10", "1d", "1e999"})
    void aWorldPropertyThatIsNotANumberIsAnErrorNamingTheRobotThePropertyAndTheValue(String value) throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> seen.add(assertThrows(IllegalStateException.class,
                () -> robot.getWorldProperty("goal", 1)).getMessage()));
        env.acceptHello();
        env.send(new Welcome("r1", 100, FakeEnvironment.state(0), Map.of("goal", value), 1));

        assertEquals("robot r1: the world's property goal is '" + value + "', not a number", nextSeen());
    }

    @Test
    void beforeItsWelcomeARobotKnowsNoPropertiesAndSeedZero() {
        TestRobot robot = new TestRobot("r1", env.port());

        assertNull(robot.getWorldProperty("cellSize"));
        assertEquals(Map.of(), robot.getWorldProperties());
        assertEquals(0, robot.getRunSeed());
    }

    // ---- state after a step ----

    @Test
    void afterAStepTheRobotHoldsTheStateThatStepBrought() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            robot.sleepSimulated(100);
            RobotState s = robot.state();
            seen.add("after step " + robot.getStep() + " at " + robot.getSimTimeMs() + " ms: (" + s.x() + ", "
                    + s.y() + ", " + s.th() + "), stalled " + s.stalled() + ", sonar "
                    + java.util.Arrays.toString(s.get(SonarReading.PART).ranges()));
        });
        welcome("r1");
        assertEquals(List.of(), env.step(1));
        env.step(2, RobotStates.of(1, 100, 50, -20, 45, 0, 0, 0, 0, true, new int[] {500, 600}, 1));
        assertEquals("after step 1 at 100 ms: (50.0, -20.0, 45.0), stalled true, sonar [500, 600]", nextSeen());
    }

    @Test
    void currentIsTheRobotInTheThreadThatConnectedItAndInThreadsThatThreadStarts() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            seen.add(AbstractRobot.current() == robot);
            Thread child = new Thread(() -> seen.add(AbstractRobot.current() == robot), "child-of-r1");
            child.start();
            RobotCode.join(child);
        });
        welcome("r1");
        assertEquals(true, nextSeen(), "the connecting thread");
        assertEquals(true, nextSeen(), "a thread it started");
        assertNull(AbstractRobot.current(), "a thread outside the robot's code");
    }

    // ---- waiting in simulated time ----

    @Test
    void sleepSimulatedWakesAtTheFirstStepAtOrAfterItsWakeTime() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            robot.sleepSimulated(250);
            robot.say("awake at " + robot.getSimTimeMs() + " ms");
        });
        welcome("r1");
        assertEquals(List.of(), env.step(1), "time 0");
        assertEquals(List.of(), env.step(2), "time 100");
        assertEquals(List.of(), env.step(3), "time 200");
        assertEquals(List.of(new Command.Say("awake at 300 ms")), env.step(4));
    }

    @Test
    void sleepSimulatedOfNothingStillYieldsAWholeStep() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            robot.sleepSimulated(0);
            robot.say("awake at " + robot.getSimTimeMs() + " ms");
        });
        welcome("r1");
        assertEquals(List.of(), env.step(1));
        assertEquals(List.of(new Command.Say("awake at 100 ms")), env.step(2));
    }

    @Test
    void eachSleepCountsFromTheTimeOfTheStepItStartsIn() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            robot.sleepSimulated(150);
            robot.say("first at " + robot.getSimTimeMs());
            robot.sleepSimulated(150);
            robot.say("second at " + robot.getSimTimeMs());
        });
        welcome("r1");
        assertEquals(List.of(), env.step(1));
        assertEquals(List.of(), env.step(2));
        assertEquals(List.of(new Command.Say("first at 200")), env.step(3));
        assertEquals(List.of(), env.step(4));
        assertEquals(List.of(new Command.Say("second at 400")), env.step(5));
    }

    @Test
    void sleepSimulatedWithoutAConnectionReturnsAtOnce() {
        TestRobot robot = new TestRobot("r1", 5000);
        robot.sleepSimulated(10_000);
        assertEquals(0, robot.getSimTimeMs());
    }

    // ---- requests and messages out ----

    @Test
    void sendBroadcastAndMulticastBecomeNumberedSendMessageCommands() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            seen.add(robot.send("r2", "hello r2"));
            seen.add(robot.broadcast(new Greeting("r1", 3)));
            seen.add(robot.multicast("team", "regroup"));
        });
        welcome("r1");
        assertEquals(List.of(
                new Command.SendMessage(1, Addressing.ROBOT, "r2", "text", "hello r2"),
                new Command.SendMessage(2, Addressing.ALL, null, "robosim.hw.AbstractRobotTest$Greeting",
                        "{\"from\":\"r1\",\"count\":3}"),
                new Command.SendMessage(3, Addressing.GROUP, "team", "text", "regroup")), env.step(1));
        assertEquals(List.of(1L, 2L, 3L), List.of(nextSeen(), nextSeen(), nextSeen()), "the numbers returned");
    }

    @Test
    void messageNumbersGoOnAcrossSteps() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            robot.send("r2", "one");
            robot.sleepSimulated(100);
            robot.send("r2", "two");
        });
        welcome("r1");
        assertEquals(List.of(new Command.SendMessage(1, Addressing.ROBOT, "r2", "text", "one")), env.step(1));
        assertEquals(List.of(new Command.SendMessage(2, Addressing.ROBOT, "r2", "text", "two")), env.step(2));
    }

    @Test
    void sayReportFoundJoinAndLeaveAreSentAsTheirCommandsInOrder() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            robot.say("hello");
            robot.reportFound("gold");
            robot.joinGroup("team");
            robot.leaveGroup("team");
        });
        welcome("r1");
        assertEquals(List.of(new Command.Say("hello"), new Command.ReportFound("gold"), new Command.JoinGroup("team"),
                new Command.LeaveGroup("team")), env.step(1));
    }

    // ---- messages and complaints in ----

    @Test
    void messagesDeliveredInAStepArePolledInDeliveryOrder() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            robot.sleepSimulated(100);
            RobotMessage text = robot.poll();
            seen.add(text.from() + " to " + text.to() + " (" + text.mode() + ", step " + text.sentStep() + "): "
                    + text.text() + ", text " + text.isText());
            RobotMessage greeting = robot.poll();
            seen.add(greeting.from() + " to " + greeting.to() + ": " + greeting.as(Greeting.class));
            seen.add(String.valueOf(robot.poll()));
        });
        welcome("r1");
        env.step(1);
        env.step(2, withMessages(1, List.of(
                new MessageDelivery("r2", Addressing.ROBOT, "r1", "text", "hi r1", 0, 7),
                new MessageDelivery("r3", Addressing.ALL, "*", "robosim.hw.AbstractRobotTest$Greeting",
                        "{\"from\":\"r3\",\"count\":2}", 1, 1)), List.of()));
        assertEquals("r2 to r1 (ROBOT, step 0): hi r1, text true", nextSeen());
        assertEquals("r3 to *: Greeting[from=r3, count=2]", nextSeen());
        assertEquals("null", nextSeen(), "no third message");
    }

    @Test
    void receiveWaitsInSimulatedTimeForTheNextMessage() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            RobotMessage m = robot.receive(1_000);
            robot.say("got " + m.text() + " at " + robot.getSimTimeMs());
        });
        welcome("r1");
        assertEquals(List.of(), env.step(1));
        assertEquals(List.of(), env.step(2));
        assertEquals(List.of(new Command.Say("got ping at 200")), env.step(3, withMessages(2,
                List.of(new MessageDelivery("r2", Addressing.ROBOT, "r1", "text", "ping", 1, 1)), List.of())));
    }

    @Test
    void receiveGivesUpWhenItsSimulatedTimeoutHasPassed() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            RobotMessage m = robot.receive(150);
            robot.say(m + " by " + robot.getSimTimeMs());
        });
        welcome("r1");
        assertEquals(List.of(), env.step(1));
        assertEquals(List.of(), env.step(2));
        assertEquals(List.of(new Command.Say("null by 200")), env.step(3));
    }

    @Test
    void theEnvironmentsComplaintsArePolledInTheOrderTheyCame() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            robot.sleepSimulated(100);
            seen.add(String.valueOf(robot.pollRequestError()));
            seen.add(String.valueOf(robot.pollRequestError()));
            seen.add(String.valueOf(robot.pollRequestError()));
        });
        welcome("r1");
        env.step(1);
        env.step(2, withMessages(1, List.of(), List.of("no robot r7 for message 1", "message 2 is over 1024 bytes")));
        assertEquals("no robot r7 for message 1", nextSeen());
        assertEquals("message 2 is over 1024 bytes", nextSeen());
        assertEquals("null", nextSeen());
    }

    @Test
    void aRequestRefusedEveryStepIsLoggedOnceASecondButEachComplaintIsPolled() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        CapturedLog log = new CapturedLog("robosim.hw");
        long started = System.nanoTime();
        try {
            run(robot, () -> {
                for (int i = 0; i < 30; i++) {
                    robot.sleepSimulated(100);
                    String e;
                    while ((e = robot.pollRequestError()) != null) {
                        seen.add(e);
                    }
                }
                seen.add("done");
            });
            welcome("r1");
            env.step(1);
            for (int step = 1; step <= 30; step++) {
                env.step(step + 1, withMessages(step, List.of(), List.of("\u001b[2Jno robot r7 for message " + step)));
            }
            for (int step = 1; step <= 30; step++) {
                assertEquals("\u001b[2Jno robot r7 for message " + step, nextSeen());
            }
            assertEquals("done", nextSeen());
            long seconds = TimeUnit.NANOSECONDS.toSeconds(System.nanoTime() - started) + 1;
            List<String> lines = log.lines();
            long logged = lines.stream().filter(l -> l.contains("the Environment refused a request")).count();
            assertTrue(logged >= 1 && logged <= seconds, "30 refusals in " + seconds + " s: " + lines);
            assertTrue(lines.stream().allMatch(l -> l.chars().allMatch(c -> c >= 0x20 && c < 0x7f)), lines.toString());
        } finally {
            log.close();
        }
    }

    // ---- the end ----

    @Test
    void aByeFromTheEnvironmentDisconnectsTheRobotAndEndsItsSleep() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        Thread t = run(robot, () -> {
            while (robot.isConnected()) {
                robot.sleepSimulated(100);
            }
            seen.add("disconnected after step " + robot.getStep());
        });
        welcome("r1");
        env.step(1);
        env.step(2);
        env.send(new Bye("the run is over"));
        assertEquals("disconnected after step 1", nextSeen());
        RobotCode.join(t);
        assertFalse(robot.isConnected());
        assertNull(env.read(), "the robot has closed its end");
    }

    @Test
    void disconnectSaysByeToTheEnvironment() throws Exception {
        TestRobot robot = new TestRobot("r1", env.port());
        run(robot, () -> {
            robot.sleepSimulated(100);
            robot.disconnect();
            seen.add("connected " + robot.isConnected());
        });
        welcome("r1");
        assertEquals(List.of(), env.step(1));
        env.send(new TimeStep(2, 100, FakeEnvironment.state(1)));
        assertEquals(new Bye("the robot's program disconnected"), assertInstanceOf(Bye.class, env.read()));
        assertEquals("connected false", nextSeen());
        assertNull(env.read(), "the robot has closed its end");
    }
}
