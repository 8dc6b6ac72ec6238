package robosim.viewer.net;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** A viewer's summary reaches the log in words, never as a record's dump. */
class ViewerSummaryTest {
    @Test
    void aSummaryIsDescribedInWords() {
        assertEquals("world 'small-maze', 601 snapshots up to step 600, ended: done: step limit 600 reached",
                new ViewerSummary("small-maze", 601, 600, "done: step limit 600 reached").describe());
        assertEquals("world 'w', 1 snapshot up to step 0, ended: stopped", new ViewerSummary("w", 1, 0, "stopped").describe());
        assertEquals("no world, no snapshot, ended: end of stream",
                new ViewerSummary(null, 0, -1, "end of stream").describe());
    }
}
