package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import robosim.protocol.RobotHello;

/** How a robot's part in a run ends: the kinds a bye names, the one-line description, the watch. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class RunEndTest {
    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "done: step limit 600 reached                          | RUN_ENDED | step limit 600 reached",
        "refused: world w has no robot named 'r9'              | REFUSED   | world w has no robot named 'r9'",
        "goodbye                                               | LEFT      | goodbye",
        "it did not send its requests for step 13 within 500 ms | DROPPED  | it did not send its requests for step 13 within 500 ms",
    })
    void aByeFromTheEnvironmentSaysHowTheRobotsPartEnded(String reason, RunEnd.Kind kind, String without) {
        assertEquals(kind, RunEnd.ofBye(reason));
        assertEquals(without, RunEnd.withoutPrefix(reason));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "RUN_ENDED     | 600 | robot r1 ran to the end of the run at 127.0.0.1:5000 after step 600: step limit 600 reached",
        "LEFT          | 40  | robot r1 left the run at 127.0.0.1:5000 after step 40: step limit 600 reached",
        "NOT_CONNECTED | 0   | robot r1 could not join the run at 127.0.0.1:5000 before step 1: step limit 600 reached",
        "REFUSED       | 0   | robot r1 was refused by the Environment at 127.0.0.1:5000 before step 1: step limit 600 reached",
        "DROPPED       | 13  | robot r1 was dropped by the Environment at 127.0.0.1:5000 after step 13: step limit 600 reached",
        "LOST          | 42  | robot r1 lost the Environment at 127.0.0.1:5000 after step 42: step limit 600 reached",
    })
    void anEndIsDescribedInOneLineWithTheRobotTheEnvironmentTheStepAndTheReason(RunEnd.Kind kind, long step,
                                                                                 String line) {
        assertEquals(line, new RunEnd("r1", kind, "127.0.0.1:5000", step, "step limit 600 reached").describe());
    }

    @Test
    void onlyTheRunsEndAndTheRobotsOwnLeaveAreNotFailures() {
        for (RunEnd.Kind kind : RunEnd.Kind.values()) {
            assertEquals(kind != RunEnd.Kind.RUN_ENDED && kind != RunEnd.Kind.LEFT, kind.isFailure(), kind.name());
        }
    }

    @Test
    void aWatchCountsTheRobotsInTheRunAndKeepsHowEachEnded() throws Exception {
        HardwareOptions options = new HardwareOptions(FakeLink.WAIT_MS, FakeLink.WAIT_MS, FakeLink.WAIT_MS);
        HardwareSimulator r1 = new HardwareSimulator(new RobotHello("r1", "pioneer", TestRobot.PARAMETERS), r -> { },
                options);
        HardwareSimulator r2 = new HardwareSimulator(new RobotHello("r2", "pioneer", TestRobot.PARAMETERS), r -> { },
                options);
        try (RunEndWatch watch = RunEndWatch.open()) {
            r1.connect(new FakeLink());
            assertEquals(1, watch.running());
            try {
                r2.connect(new FakeLink(new IOException("no Environment at fake:1 within 10 ms")));
            } catch (IOException expected) {
                // r2 never joined
            }
            assertEquals(1, watch.running(), "r2 ended as it failed to connect");
            assertFalse(watch.awaitNoneRunning(10), "r1 is still in the run");

            r1.ended(RunEnd.Kind.LOST, "it closed the connection without a bye");

            assertTrue(watch.awaitNoneRunning(FakeLink.WAIT_MS));
            assertEquals(List.of(
                    new RunEnd("r2", RunEnd.Kind.NOT_CONNECTED, "fake:1", 0, "no Environment at fake:1 within 10 ms"),
                    new RunEnd("r1", RunEnd.Kind.LOST, "fake:1", 0, "it closed the connection without a bye")),
                    watch.ends());
        } finally {
            r1.ended(RunEnd.Kind.RUN_ENDED, "the test is over");
        }
    }
}
