package robosim.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/** How the benchmark cuts a run into windows of steps and reads a client's windows from its log. */
class StepWindowsTest {
    /** A clock, CPU time and allocation that each go up by a fixed amount per step. */
    private final AtomicLong step = new AtomicLong();
    private final StepWindows windows = new StepWindows(100, () -> step.get() * 2_000_000L,
            () -> step.get() * 500_000L, () -> step.get() * 4096L, () -> step.get() / 100);

    private void runTo(long last, long by) {
        for (long s = step.get(); s <= last; s += by) {
            step.set(s);
            windows.at(s);
        }
    }

    @Test
    void eachWindowStartsWhereTheLastEndedAndTheEndClosesTheLast() {
        step.set(1);
        windows.at(1);
        runTo(250, 1);
        windows.end(250);
        List<StepWindows.Window> w = windows.windows();
        assertEquals(List.of(1L, 100L, 200L), w.stream().map(StepWindows.Window::from).toList());
        assertEquals(List.of(100L, 200L, 250L), w.stream().map(StepWindows.Window::to).toList());
        StepWindows.Window second = w.get(1);
        assertEquals(500, second.stepsPerSecond(), 1e-9, "2 ms a step");
        assertEquals(500, second.cpuMicrosPerStep(), 1e-9);
        assertEquals(4, second.allocatedKibPerStep(), 1e-9);
        assertEquals(2, second.stalled(), "counted at its end");
    }

    @Test
    void aMarkSeenLateCountsTheStepsItReallyCovers() {
        step.set(0);
        windows.at(0);
        runTo(400, 70);
        windows.end(400);
        assertEquals(List.of(140L, 210L, 350L, 400L),
                windows.windows().stream().map(StepWindows.Window::to).toList(), "the first step at or past 100, 200, 300");
    }

    @Test
    void theEndAtAStepAlreadyMarkedAddsNoEmptyWindow() {
        step.set(0);
        windows.at(0);
        runTo(200, 100);
        windows.end(200);
        assertEquals(2, windows.windows().size());
    }

    @Test
    void aClientsWindowsAreReadBackFromItsLine() {
        step.set(1);
        windows.at(1);
        runTo(300, 1);
        windows.end(300);
        List<String> log = List.of("INFO: all 30 robots connected", windows.clientLine(),
                JvmMemory.clientLine(java.util.Map.of("rss_mb", "1.0")));
        assertEquals(Optional.of(windows.windows()), StepWindows.clientWindows(log));
    }

    @Test
    void aLogWithoutWindowsOrWithABrokenLineGivesNone() {
        assertEquals(Optional.empty(), StepWindows.clientWindows(List.of("INFO: nothing")));
        assertEquals(Optional.empty(), StepWindows.clientWindows(List.of("bench-windows 1:2:3:4")));
    }

    @Test
    void whatTheJvmDoesNotTellStaysUnknown() {
        StepWindows blind = new StepWindows(10, System::nanoTime, () -> -1, () -> -1, () -> -1);
        blind.at(0);
        blind.end(10);
        StepWindows.Window w = blind.windows().get(0);
        assertEquals(-1, w.cpuMicrosPerStep());
        assertEquals(-1, w.allocatedKibPerStep());
        assertEquals(-1, w.stalled());
        assertTrue(StepWindows.processCpuNanos() != 0);
    }

    @Test
    void aWindowOfNoStepsIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new StepWindows(0));
    }
}
