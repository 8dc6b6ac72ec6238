package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(10)
class LogLimiterTest {
    private final Logger log = Logger.getLogger("robosim.test.LogLimiterTest");
    private final List<String> lines = new CopyOnWriteArrayList<>();
    private final Handler capture = new Handler() {
        @Override
        public void publish(LogRecord r) {
            lines.add(r.getMessage());
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    };
    private final AtomicLong now = new AtomicLong(1_000_000_000L);

    @BeforeEach
    void capture() {
        log.setUseParentHandlers(false);
        log.addHandler(capture);
    }

    @AfterEach
    void release() {
        log.removeHandler(capture);
    }

    private void advanceMs(long ms) {
        now.addAndGet(TimeUnit.MILLISECONDS.toNanos(ms));
    }

    @Test
    void aFloodCostsALineAPeriodAndItsCount() {
        LogLimiter limiter = new LogLimiter(log, 1000, now::get, false);
        for (int i = 0; i < 100_000; i++) {
            int n = i;
            limiter.warning("bad packets", () -> "bad packet " + n);
        }
        assertEquals(List.of("bad packet 0"), lines);
        assertEquals(99_999, limiter.suppressed("bad packets"));
        advanceMs(1000);
        limiter.flush();
        assertEquals(List.of("bad packet 0", "99999 more bad packets in the last 1000 ms, not logged one by one"), lines);
        // the flood goes on: the next period counts again, so a flood is one line a period
        limiter.warning("bad packets", () -> "bad packet again");
        assertEquals(2, lines.size());
        advanceMs(1000);
        limiter.flush();
        assertEquals("1 more bad packets in the last 1000 ms, not logged one by one", lines.get(2));
        // a quiet period ends it: the next line is whole again
        advanceMs(1000);
        limiter.flush();
        assertTrue(limiter.warning("bad packets", () -> "after the quiet"));
        assertEquals("after the quiet", lines.get(3));
    }

    @Test
    void kindsAreCountedApart() {
        LogLimiter limiter = new LogLimiter(log, 1000, now::get, false);
        assertTrue(limiter.info("messages", () -> "m1"));
        assertTrue(limiter.info("sounds", () -> "s1"));
        assertFalse(limiter.info("messages", () -> "m2"));
        assertEquals(List.of("m1", "s1"), lines);
        assertEquals(1, limiter.suppressed("messages"));
        assertEquals(0, limiter.suppressed("sounds"));
    }

    @Test
    void aLineNotLoggedIsNeverMade() {
        LogLimiter limiter = new LogLimiter(log, 1000, now::get, false);
        limiter.warning("k", () -> "first");
        limiter.warning("k", () -> {
            throw new AssertionError("a suppressed line must not be built");
        });
    }

    @Test
    void theCountOfAFloodsLastPeriodIsLoggedWithoutAnotherLine() {
        // a period long enough that the ten calls fall in it however busy the machine
        LogLimiter limiter = new LogLimiter(log, 250, System::nanoTime, true);
        for (int i = 0; i < 10; i++) {
            limiter.warning("bursts", () -> "burst");
        }
        Await.until(Duration.ofSeconds(5), "the count line after the burst's period", () -> lines.size() >= 2);
        assertEquals(List.of("burst", "9 more bursts in the last 250 ms, not logged one by one"), lines);
    }

    @Test
    void anExcerptIsShortAndEscaped() {
        String hostile = "\u001b[2J\u0007" + "x".repeat(10_000_000);
        String e = LogLimiter.excerpt(hostile);
        assertTrue(e.length() < 120, e);
        assertFalse(e.chars().anyMatch(c -> c < 0x20 || c >= 0x7f), e);
        assertTrue(e.startsWith("\\u001b[2J\\u0007x"), e);
        assertTrue(e.endsWith("(10000005 characters)"), e);
    }
}
