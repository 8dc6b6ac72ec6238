package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.hw.FakeLink.WAIT_MS;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Command;
import robosim.protocol.Figure;
import robosim.protocol.MessageDelivery;
import robosim.protocol.RobotState;
import robosim.protocol.RobotStates;

/**
 * What every Robot-Object shares, over a {@link FakeLink}: no connection and no Environment, the
 * test delivering each step itself.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class AbstractRobotUnitTest {
    private static final HardwareOptions OPTIONS = new HardwareOptions(WAIT_MS, WAIT_MS, WAIT_MS);

    private final RobotCode code = new RobotCode();
    private final FakeLink link = new FakeLink();
    private final TestRobot robot = new TestRobot("r1", 1);

    @AfterEach
    void end() throws InterruptedException {
        if (link.receiver != null) {
            link.receiver.ended(RunEnd.Kind.RUN_ENDED, "the test is over");
        }
        code.close();
    }

    /** Connects the robot over the fake link on a code thread, then runs {@code body} there. */
    private Thread run(RobotCode.Body body) throws InterruptedException {
        CountDownLatch connected = new CountDownLatch(1);
        Thread t = code.start("code", () -> {
            robot.connect(OPTIONS, link);
            connected.countDown();
            body.run();
        });
        assertTrue(connected.await(WAIT_MS, TimeUnit.MILLISECONDS));
        return t;
    }

    @Test
    void aConnectedRobotHoldsItsWelcomeAndSaysHelloWithItsParameters() throws Exception {
        run(() -> { });
        assertTrue(robot.isConnected());
        assertEquals(FakeLink.state(0).x(), robot.welcomedWith.x());
        assertEquals(100, robot.getStepMs());
        assertEquals(TestRobot.PARAMETERS, link.hello.parameters());
        assertEquals("pioneer", link.hello.robotType());
    }

    @Test
    void sleepSimulatedWakesAtTheFirstStepAtOrAfterItsWakeTime() throws Exception {
        AtomicLong wokeAt = new AtomicLong(-1);
        Thread t = run(() -> {
            robot.sleepSimulated(250);
            wokeAt.set(robot.getSimTimeMs());
        });
        for (long step = 1; step <= 3; step++) {
            link.step(step);
            link.next();
            assertEquals(-1, wokeAt.get(), "still asleep at " + (step - 1) * 100 + " ms");
        }
        link.step(4);
        RobotCode.join(t);
        assertEquals(300, wokeAt.get());
    }

    @Test
    void commandsLeaveAsTheStepsRobotRequests() throws Exception {
        run(() -> {
            robot.say("hello");
            robot.joinGroup("team");
            robot.sleepSimulated(100);
        });
        link.step(1);
        assertEquals(List.of(new RobotRequest(new Command.Say("hello")), new RobotRequest(new Command.JoinGroup("team"))),
                link.next().requests());
    }

    @Test
    void aDrawingAndItsClearingLeaveAsTheStepsRobotRequests() throws Exception {
        Figure cell = new Figure(Figure.CELLS, "", new double[] {0, 0, 500, 500});
        run(() -> {
            robot.draw("map", List.of(cell));
            robot.clearDrawing("frontier");
            robot.sleepSimulated(100);
        });
        link.step(1);
        assertEquals(List.of(new RobotRequest(new Command.Draw("map", List.of(cell))),
                new RobotRequest(new Command.Draw("frontier", List.of()))), link.next().requests());
    }

    @Test
    void metricsAndAnEndRequestLeaveWithTheStepsRobotRequests() throws Exception {
        run(() -> {
            robot.reportMetric("cellsExplored", 12);
            robot.endRun("gold found");
            robot.sleepSimulated(100);
        });
        link.step(1);
        assertEquals(List.of(new RobotRequest(new Command.ReportMetric("cellsExplored", 12)),
                new RobotRequest(new Command.EndRun("gold found"))), link.next().requests());
    }

    @Test
    void aMetricOrAReasonThatBreaksItsRuleIsRefusedAtTheCallAndNothingIsSent() throws Exception {
        String[] refused = new String[3];
        run(() -> {
            refused[0] = assertThrows(IllegalArgumentException.class,
                    () -> robot.reportMetric("cells explored", 1)).getMessage();
            refused[1] = assertThrows(IllegalArgumentException.class,
                    () -> robot.reportMetric("cells", Double.NaN)).getMessage();
            refused[2] = assertThrows(IllegalArgumentException.class, () -> robot.endRun("")).getMessage();
            robot.say("after");
            robot.sleepSimulated(100);
        });
        link.step(1);
        assertEquals(List.of(new RobotRequest(new Command.Say("after"))), link.next().requests());
        assertEquals("'cells explored' was supplied for a metric's name: a letter, then up to 63 letters, digits,"
                + " '_', '.' or '-'", refused[0]);
        assertEquals("NaN was supplied for metric cells: it must be a finite number", refused[1]);
        assertEquals("a reason of 0 characters was supplied for ending the run: 1 to 200 characters", refused[2]);
    }

    @Test
    void messagesAndComplaintsInAResponseAreHeldForTheCodeInOrder() throws Exception {
        CountDownLatch polled = new CountDownLatch(1);
        String[] seen = new String[3];
        run(() -> {
            robot.sleepSimulated(100);
            seen[0] = robot.poll().text();
            seen[1] = robot.poll().text();
            seen[2] = robot.pollRequestError();
            polled.countDown();
            robot.sleepSimulated(10_000);
        });
        link.step(1);
        link.next();
        RobotState s = FakeLink.state(1);
        link.receiver.step(new RobotSensorResponse(2, RobotStates.of(s.step(), s.timeMs(), 0, 0, 0, 0, 0, 0, 0, false,
                new int[0], 0, new int[0], null,
                List.of(new MessageDelivery("r2", Command.Addressing.ROBOT, "r1", "text", "first", 1, 1),
                        new MessageDelivery("r3", Command.Addressing.ALL, null, "text", "second", 1, 4)),
                List.of("message 2 is addressed to 'nobody'"), 0)));
        assertTrue(polled.await(WAIT_MS, TimeUnit.MILLISECONDS));
        assertEquals("first", seen[0]);
        assertEquals("second", seen[1]);
        assertEquals("message 2 is addressed to 'nobody'", seen[2]);
        assertNull(robot.pollRequestError());
    }

    @Test
    void aRobotThatCouldNotConnectIsNotConnectedAndItsCallsReturn() throws Exception {
        FakeLink refusing = new FakeLink(new IOException("the Environment at here refused: no robot r1"));

        Thread t = code.start("code", () -> {
            try {
                robot.connect(OPTIONS, refusing);
            } catch (IOException expected) {
                // as tryConnect records it
            }
            robot.sleepSimulated(1_000);
            robot.disconnect();
        });

        RobotCode.join(t);
        assertFalse(robot.isConnected());
        assertEquals(0, robot.getSimTimeMs());
    }
}
