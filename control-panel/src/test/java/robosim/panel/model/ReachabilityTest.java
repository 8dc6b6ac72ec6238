package robosim.panel.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import robosim.panel.model.Reachability.Failure;

/** How the panel fares with its Environment: what it says, once, and when it asks again. */
class ReachabilityTest {
    private final Reachability r = new Reachability("localhost:3000", 500);

    @Test
    void aPanelAttachedFirstWaitsQuietlyWithGrowingPausesThenAttaches() {
        assertEquals("waiting for the Environment at localhost:3000 to start (Connection refused)",
                r.failed(Failure.UNREACHABLE, "Connection refused"));
        assertEquals(500, r.nextDelayMs());
        assertNull(r.failed(Failure.UNREACHABLE, "Connection refused"), "said once");
        assertEquals(1000, r.nextDelayMs());
        for (int i = 0; i < 10; i++) {
            assertNull(r.failed(Failure.UNREACHABLE, "Connection refused"));
        }
        assertEquals(Reachability.MAX_RETRY_MS, r.nextDelayMs());
        assertEquals("waiting for the Environment at localhost:3000 to start (trying again every 5 s)", r.line());

        assertNull(r.reached(), "the first status needs no word");
        assertTrue(r.attached());
        assertNull(r.line());
        assertEquals(500, r.nextDelayMs());
    }

    @Test
    void aNewerSecretIsTriedAtOnceAndSaysNothing() {
        r.failed(Failure.NO_SECRET, "presented no run secret");
        assertNull(r.failed(Failure.SECRET_CHANGED, "presented no run secret"));
        assertEquals(500, r.nextDelayMs());
    }

    @Test
    void aFinalRefusalIsSaidOnceAndTriedRarely() {
        String said = r.failed(Failure.SECRET_REFUSED, "presented a wrong run secret");
        assertTrue(said.startsWith("the Environment at localhost:3000 refuses this panel: presented a wrong run secret;"
                + " trying again every 30 s"), said);
        assertNull(r.failed(Failure.SECRET_REFUSED, "presented a wrong run secret"));
        assertEquals(Reachability.REFUSED_RETRY_MS, r.nextDelayMs());
        assertEquals("refused: presented a wrong run secret (trying again every 30 s)", r.line());
    }

    @Test
    void anEnvironmentThatWasThereAndNoLongerAnswersIsGoneAndSaysSoWhenBack() {
        r.reached();
        assertEquals("the Environment at localhost:3000 is gone (Connection refused); trying again every 5 s",
                r.failed(Failure.UNREACHABLE, "Connection refused"));
        assertEquals("Environment gone: localhost:3000 does not answer (trying again every 0.5 s)", r.line());
        assertEquals("the Environment at localhost:3000 answers again", r.reached());
    }

    @Test
    void aStoppedRunStaysStoppedWhileItsEnvironmentIsSilent() {
        r.reached();
        assertEquals("the run at localhost:3000 has stopped: stopped by control client 'panel'",
                r.failed(Failure.ENDED, "stopped by control client 'panel'"));
        assertNull(r.failed(Failure.UNREACHABLE, "Connection refused"));
        assertNull(r.failed(Failure.UNREACHABLE, "Connection refused"));
        assertEquals("stopped: stopped by control client 'panel'", r.line());
        assertTrue(r.nextDelayMs() > 500, "it backs off");
    }

    @Test
    void aPeriodBelowOneMillisecondIsRefused() {
        assertEquals("0 was supplied for periodMs: it must be at least 1 ms",
                assertThrows(IllegalArgumentException.class, () -> new Reachability("h:1", 0)).getMessage());
    }
}
