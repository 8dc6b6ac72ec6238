package robosim.scout;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;
import robosim.protocol.RobotState;

/** conf_tm's motion timeout and ws's wait, in simulated time. */
class MotionTimingTest {
    private final ScriptedScout scout = new ScriptedScout();

    private static RobotState moving(long step, double wheels) {
        return ScriptedScout.at(step, 0, 0, 0, wheels, wheels, new int[0], 0);
    }

    /** Steps the robot to {@code step} with both wheels turning, returning what it sent meanwhile. */
    private List<Command> runTo(long from, long to) {
        scout.sent.clear();
        for (long k = from; k <= to; k++) {
            scout.deliver(moving(k, 200));
        }
        return List.copyOf(scout.sent);
    }

    @Test
    void conf_tmStopsOnceTheTimeoutHasPassedSinceTheLastMotionCommand() {
        assertTrue(scout.conf_tm(1));
        assertTrue(scout.vm(100, 100, 0)); // at time 0
        assertEquals(List.of(), runTo(1, 9), "900 ms: still within the timeout");
        assertEquals(List.of(new Command.Stop()), runTo(10, 10), "at 1000 ms the robot is stopped");
        assertEquals(List.of(), runTo(11, 30), "once only");
    }

    @Test
    void aNewMotionCommandRestartsTheTimeout() {
        assertTrue(scout.conf_tm(2));
        assertTrue(scout.pr(100, 100, 0));
        runTo(1, 15);
        assertTrue(scout.scout_vm(100, 0)); // at 1500 ms
        assertEquals(List.of(), runTo(16, 34));
        assertEquals(List.of(new Command.Stop()), runTo(35, 35));
    }

    @Test
    void stopDisarmsAndZeroSwitchesTheTimeoutOff() {
        assertTrue(scout.conf_tm(1));
        assertTrue(scout.vm(100, 100, 0));
        assertTrue(scout.st());
        assertEquals(List.of(), runTo(1, 20), "a stopped robot is not stopped again");
        assertTrue(scout.conf_tm(0));
        assertTrue(scout.vm(100, 100, 0));
        assertEquals(List.of(), runTo(21, 100));
    }

    @Test
    void conf_tmRefusesTimeoutsBeyondAByte() {
        assertFalse(scout.conf_tm(-1));
        assertFalse(scout.conf_tm(256));
        assertTrue(scout.conf_tm(255));
    }

    @Test
    void wsReturnsTrueOnceTheNamedWheelsHaveStopped() {
        // the command just made shows in the next state: ws waits at least a step
        scout.queue(moving(1, 100), moving(2, 300), moving(3, 100), ScriptedScout.at(4, 0, 0, 0, 0, 40, new int[0], 0),
                moving(5, 0));
        assertTrue(scout.pr(200, 200, 0));
        assertTrue(scout.ws(0, 1, 0, 10), "the left wheel stopped at step 4");
        assertEquals(4, scout.getStateStep());
        assertTrue(scout.ws(1, 1, 0, 10));
        assertEquals(5, scout.getStateStep());
    }

    @Test
    void wsTimesOutInSimulatedSeconds() {
        scout.deliver(moving(3, 100)); // now 300 ms
        assertFalse(scout.ws(1, 1, 0, 2), "the wheels never stop");
        assertEquals(23, scout.getStateStep(), "2 s after the call");
    }

    @Test
    void wsWithNoAxesReturnsAfterOneStep() {
        scout.deliver(moving(3, 100));
        assertTrue(scout.ws(0, 0, 0, 1));
        assertEquals(4, scout.getStateStep());
    }
}
