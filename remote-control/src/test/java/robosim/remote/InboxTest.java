package robosim.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The list of messages received. */
class InboxTest {
    @Test
    void aTextToEveryoneReadsAsToAll() {
        assertEquals("step 12, from r2 to all: hello", Inbox.line(12, "r2", "*", "text", "hello"));
    }

    @Test
    void anObjectShowsItsClassAndJson() {
        assertEquals("step 3, from r2 to r1: robosim.Gold {\"x\":1}", Inbox.line(3, "r2", "r1", "robosim.Gold", "{\"x\":1}"));
    }

    @Test
    void onlyTheLatestAreKeptButAllAreCounted() {
        Inbox inbox = new Inbox();
        for (int i = 0; i < Inbox.KEPT + 5; i++) {
            inbox.add("m" + i);
        }
        assertEquals(Inbox.KEPT, inbox.lines().size());
        assertEquals("m5", inbox.lines().get(0));
        assertEquals(Inbox.KEPT + 5, inbox.total());
    }
}
