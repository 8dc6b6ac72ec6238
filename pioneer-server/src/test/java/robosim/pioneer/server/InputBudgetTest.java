package robosim.pioneer.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** How much of a client's input is read a cycle, and when a client counts as flooding. */
class InputBudgetTest {
    private static final long MS = TimeUnit.MILLISECONDS.toNanos(1);

    @Test
    void anAriaProgramsTrafficIsNeverHeldBack() {
        InputBudget b = new InputBudget(0);
        // a few commands and a PULSE every cycle, for a minute
        for (long t = 0; t < 60_000; t += InputBudget.CYCLE_MS) {
            assertEquals(0, b.spent(60, 6, t * MS));
            assertFalse(b.flooding(t * MS));
        }
    }

    @Test
    void aClientOverItsBudgetWaitsForTheNextCycleAndWhatWentOverCountsThere() {
        InputBudget b = new InputBudget(0);
        assertEquals(0, b.spent(512, 100, 10 * MS));
        assertEquals(90 * MS, b.spent(512, 100, 10 * MS), "200 packets: the rest of the cycle");
        // read again as the next cycle starts: it is over again at once only when it goes over again
        assertEquals(0, b.spent(512, 100, 100 * MS));
        assertEquals(100 * MS, b.spent(512, 100, 100 * MS));
    }

    @Test
    void bytesThatMakeNoPacketCountToo() {
        InputBudget b = new InputBudget(0);
        long wait = 0;
        for (int i = 0; i < 16 && wait == 0; i++) {
            wait = b.spent(512, 0, 0);
        }
        assertEquals(100 * MS, wait, "8 KB of garbage in a cycle");
    }

    @Test
    void aClientThatKeepsOverItsBudgetForFiveSecondsIsFlooding() {
        InputBudget b = new InputBudget(0);
        long now = 0;
        while (!b.flooding(now)) {
            long wait = b.spent(512, 57, now);
            now += wait > 0 ? wait : MS;
            assertTrue(now < 6000 * MS, "flooding by " + now / MS + " ms");
        }
        assertTrue(now > InputBudget.FLOODING_MS * MS, "not before " + InputBudget.FLOODING_MS + " ms: " + now / MS);
        // a cycle within the budget ends it
        assertEquals(0, b.spent(10, 1, now + 200 * MS));
        assertFalse(b.flooding(now + 200 * MS));
    }
}
