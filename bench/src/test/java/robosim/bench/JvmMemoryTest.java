package robosim.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/** How the benchmark reads a process's resident set and a client's figures, and samples the heap. */
class JvmMemoryTest {
    private static final String STATUS = """
            Name:\tjava
            Umask:\t0022
            State:\tS (sleeping)
            Pid:\t4242
            VmPeak:\t 9876543 kB
            VmSize:\t 9876000 kB
            VmHWM:\t  523456 kB
            VmRSS:\t  412345 kB
            RssAnon:\t  400000 kB
            Threads:\t2031
            """;

    @Test
    void theResidentSetComesFromVmRssAndVmHwm() {
        assertEquals(Optional.of(new JvmMemory.Resident(412345, 523456)), JvmMemory.parseStatus(STATUS));
    }

    @Test
    void aFieldIsFoundByItsWholeName() {
        assertEquals(OptionalLong.of(400000), JvmMemory.statusKb(STATUS, "RssAnon"));
        assertEquals(OptionalLong.empty(), JvmMemory.statusKb(STATUS, "Rss"), "not a prefix of another field");
        assertEquals(OptionalLong.empty(), JvmMemory.statusKb(STATUS, "Threads"), "a count, not kB");
        assertEquals(OptionalLong.empty(), JvmMemory.statusKb("VmRSS:\tmany kB\n", "VmRSS"));
    }

    @Test
    void aStatusWithoutTheResidentSetGivesNone() {
        assertEquals(Optional.empty(), JvmMemory.parseStatus("Name:\tjava\nVmRSS:\t 12 kB\n"), "no VmHWM");
        assertEquals(Optional.empty(), JvmMemory.parseStatus(""));
        assertEquals(Optional.empty(), JvmMemory.resident(Path.of("/no/such/proc/status")), "not Linux");
    }

    @Test
    void aClientsFiguresAreOnItsLastMarkedLine() {
        Map<String, String> figures = new LinkedHashMap<>();
        figures.put("rss_mb", "410.5");
        figures.put("heap_gc_mb", "unavailable");
        figures.put("heap_samples", "100:3.1,200:3.2");
        List<String> log = List.of(
                "Nov 23, 2026 1:52:50 PM robosim.bench.BenchRobots lambda$main$2",
                "INFO: all 10 robots connected 736 ms after this JVM started",
                JvmMemory.clientLine(Map.of("rss_mb", "1.0")),
                JvmMemory.clientLine(figures),
                "bench-memoryless line");
        Map<String, String> read = JvmMemory.clientFigures(log).orElseThrow();
        assertEquals(figures, read);
        assertEquals(List.copyOf(figures.keySet()), List.copyOf(read.keySet()), "in the order printed");
        assertEquals("rss_mb=410.5 heap_gc_mb=unavailable heap_samples=100:3.1,200:3.2", JvmMemory.fields(read));
        assertEquals(Optional.empty(), JvmMemory.clientFigures(List.of("INFO: nothing", "")));
    }

    @Test
    void theSamplerTakesOneSampleAtOrPastEachMultipleAndNoneTwiceAtAStep() {
        AtomicLong heap = new AtomicLong(1024 * 1024);
        JvmMemory.Sampler s = new JvmMemory.Sampler(100, heap::get);
        for (long step = 0; step <= 250; step++) {
            s.at(step);
            heap.addAndGet(1024 * 1024 / 10);
        }
        s.at(399); // a late look: the sample says when it was taken
        s.at(400);
        s.add(400);
        s.add(410);
        assertEquals("100:11.00,200:21.00,399:26.10,400:26.10,410:26.10", s.samples());
        assertEquals("", new JvmMemory.Sampler(5).samples());
        assertThrows(IllegalArgumentException.class, () -> new JvmMemory.Sampler(0));
    }

    @Test
    void aSampleTheJvmCannotGiveSaysSo() {
        JvmMemory.Sampler s = new JvmMemory.Sampler(1, () -> -1);
        s.at(1);
        assertEquals("1:unavailable", s.samples());
    }

    @Test
    void thisJvmsFiguresHaveEveryKeyAndAHeapAfterAFullCollection() {
        Map<String, String> f = JvmMemory.figures(null);
        assertEquals(List.of("rss_mb", "hwm_mb", "heap_gc_mb", "heap_committed_mb", "gcs", "heap_live_mb"),
                List.copyOf(f.keySet()));
        assertTrue(Double.parseDouble(f.get("heap_live_mb")) > 0, f.toString());
        assertTrue(JvmMemory.heapAfterLastGc() > 0, "the full collection just forced is the last one");
    }
}
