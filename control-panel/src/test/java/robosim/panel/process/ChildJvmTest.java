package robosim.panel.process;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.protocol.Await;

@Timeout(value = 60, unit = TimeUnit.SECONDS)
class ChildJvmTest {
    private static List<String> awaitLines(List<String> lines, int n) {
        Await.within(Await.PATIENCE, () -> lines.size() >= n); // fewer lines fail the caller's check, which shows them
        return List.copyOf(lines);
    }

    @Test
    void eachOutputLineReachesTheSinkWithTheVariablesGiven() throws Exception {
        List<String> lines = new CopyOnWriteArrayList<>();
        try (ChildJvm jvm = ChildJvm.start("sleeper", null, Sleeper.class.getName(), List.of("a", "b"),
                Map.of("ROBOSIM_TEST_VAR", "x1"), lines::add)) {
            assertEquals(List.of("args: a b", "var: x1"), awaitLines(lines, 2));
        }
    }

    @Test
    void stopEndsTheJvmAndTheProcessesItStarted() throws Exception {
        List<String> lines = new CopyOnWriteArrayList<>();
        ChildJvm jvm = ChildJvm.start("sleeper", null, Sleeper.class.getName(), List.of("child"), Map.of(), lines::add);
        List<String> seen = awaitLines(lines, 3);
        long childPid = Long.parseLong(seen.get(2).substring("child: ".length()));
        Optional<ProcessHandle> child = ProcessHandle.of(childPid);
        assertTrue(child.isPresent() && child.get().isAlive(), "the grandchild runs before the stop");

        jvm.stop();

        assertFalse(jvm.isAlive());
        child.get().onExit().get(10, TimeUnit.SECONDS);
        assertFalse(child.get().isAlive());
    }
}
