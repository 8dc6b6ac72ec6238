package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** ARIA's key handler reading keys from a stream: characters, escape sequences, handlers. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ArKeyHandlerTest {
    private static ArKeyHandler reading(String text) {
        return new ArKeyHandler(true, false, new ByteArrayInputStream(text.getBytes(StandardCharsets.ISO_8859_1)), true);
    }

    @Test
    void escapeSequencesBecomeAriasCodesAndOtherKeysTheirCharacters() {
        ArKeyHandler keys = reading("a \t\n\u007f\u001b[A\u001b[B\u001b[C\u001b[D\u001bOP\u001b[15~\u001b[2~\u001b[3~\u001b[5~Z\u001b");
        List<Integer> got = new ArrayList<>();
        for (int k = keys.getKey(); k != -1; k = keys.getKey()) {
            got.add(k);
        }
        assertEquals(List.of((int) 'a', ArKeyHandler.SPACE, ArKeyHandler.TAB, ArKeyHandler.ENTER, ArKeyHandler.BACKSPACE,
                ArKeyHandler.UP, ArKeyHandler.DOWN, ArKeyHandler.RIGHT, ArKeyHandler.LEFT, ArKeyHandler.F1,
                ArKeyHandler.F5, ArKeyHandler.INSERT, ArKeyHandler.DEL, ArKeyHandler.PAGEUP, (int) 'Z',
                ArKeyHandler.ESCAPE), got);
    }

    @Test
    void eachKeyRunsItsHandlerAndASecondHandlerForAKeyIsRefused() {
        ByteArrayOutputStream log = new ByteArrayOutputStream();
        ArLog.setStream(new PrintStream(log, true, StandardCharsets.UTF_8));
        try {
            ArKeyHandler keys = reading("ww s\u001b[A");
            List<String> done = new ArrayList<>();
            assertTrue(keys.addKeyHandler('w', () -> done.add("faster")));
            assertTrue(keys.addKeyHandler(ArKeyHandler.SPACE, () -> done.add("stop")));
            assertTrue(keys.addKeyHandler(ArKeyHandler.UP, () -> done.add("up")));
            assertFalse(keys.addKeyHandler('w', () -> done.add("again")));
            assertTrue(log.toString(StandardCharsets.UTF_8).contains("There is already a key to handle 'w' which is"
                    + " number 119 0x77"), log.toString(StandardCharsets.UTF_8));
            keys.checkKeys();
            assertEquals(List.of("faster", "faster", "stop", "up"), done, "'s' has no handler");
            assertTrue(keys.remKeyHandler('w'));
            assertFalse(keys.remKeyHandler('w'));
            keys.restore();
        } finally {
            ArLog.setStream(null);
        }
    }
}
