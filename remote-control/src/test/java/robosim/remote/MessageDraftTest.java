package robosim.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class MessageDraftTest {
    @Test
    void aMessageToAllNeedsNoName() {
        MessageDraft m = MessageDraft.of(MessageDraft.To.ALL, "ignored", "  hello  ");
        assertNull(m.name());
        assertEquals("hello", m.text());
        assertEquals("all", m.recipient());
    }

    @Test
    void aMessageToARobotWithoutItsNameIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> MessageDraft.of(MessageDraft.To.ROBOT, " ", "hi"));
        assertEquals("no robot was supplied for to: a message to one robot needs its name", e.getMessage());
    }

    @Test
    void aNameWithSpacesIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> MessageDraft.of(MessageDraft.To.GROUP, "red team", "hi"));
        assertEquals("'red team' was supplied for to: a name is 1 to 64 letters, digits, '_', '.' or '-'", e.getMessage());
    }

    @Test
    void anEmptyOrOverlongTextIsRefused() {
        assertEquals("a message of 0 characters was supplied: a message is 1 to 1000 characters",
                assertThrows(IllegalArgumentException.class, () -> MessageDraft.of(MessageDraft.To.ALL, null, " "))
                        .getMessage());
        assertThrows(IllegalArgumentException.class, () -> MessageDraft.of(MessageDraft.To.ALL, null, "x".repeat(1001)));
    }
}
