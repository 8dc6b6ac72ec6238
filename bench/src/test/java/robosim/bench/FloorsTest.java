package robosim.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The floors' measurement runs to its end and reports each figure; how fast is not tested. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class FloorsTest {
    @Test
    void eachFloorIsMeasuredAndPrintedOnOneLine() throws InterruptedException {
        Floors.Figures f = Floors.measure(200);

        assertTrue(f.platformHandOffMicros() > 0 && Double.isFinite(f.platformHandOffMicros()), f.toString());
        assertTrue(f.loopbackRoundTripMicros() > 0 && Double.isFinite(f.loopbackRoundTripMicros()), f.toString());
        assertEquals(Runtime.version().feature() >= 21, Double.isFinite(f.virtualHandOffMicros()), f.toString());
        StringWriter text = new StringWriter();
        Floors.print(new PrintWriter(text), f);
        assertTrue(text.toString().matches("floors java=\\d+ platform_handoff_us=[0-9.]+ virtual_handoff_us=([0-9.]+|none)"
                + " loopback_rtt_us=[0-9.]+\\R"), text.toString());
    }
}
