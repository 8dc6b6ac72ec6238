package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(10)
class AwaitTest {
    @Test
    void aConditionThatHoldsEndsTheWaitAtOnce() {
        long start = System.nanoTime();
        Await.until(Duration.ofSeconds(5), "true", () -> true);
        assertTrue(System.nanoTime() - start < Duration.ofSeconds(1).toNanos());
    }

    @Test
    void theConditionIsLookedAtAgainUntilItHolds() {
        AtomicInteger looks = new AtomicInteger();
        Await.until(Duration.ofSeconds(5), "the fifth look", () -> looks.incrementAndGet() == 5);
        assertEquals(5, looks.get());
    }

    @Test
    void aConditionThatNeverHoldsFailsAtTheDeadlineSayingWhatWasAwaited() {
        long start = System.nanoTime();
        AssertionError e = assertThrows(AssertionError.class,
                () -> Await.until(Duration.ofMillis(50), "the moon", () -> false));
        assertEquals("not within 50 ms: the moon", e.getMessage());
        assertTrue(System.nanoTime() - start >= Duration.ofMillis(50).toNanos());
        assertFalse(Await.within(Duration.ofMillis(20), () -> false));
    }

    @Test
    void aValueIsTheFirstOneTheProbeGives() {
        AtomicInteger looks = new AtomicInteger();
        assertEquals("3", Await.value(Duration.ofSeconds(5), "a third look",
                () -> looks.incrementAndGet() >= 3 ? Integer.toString(looks.get()) : null));
    }
}
