package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import robosim.protocol.MessageCodec.Format;

class LogLineTest {
    private final MessageCodec json = new MessageCodec(Format.JSON);

    @Test
    void aLineCrossesTheWireUnchanged() throws FrameException {
        LogLine line = new LogLine(42, "WARNING", "closing robot r1: removed by control client ctl after step 42");

        assertEquals(line, json.decode(json.encode(line)));
    }

    @Test
    void aLevelOtherThanSevereWarningOrInfoIsRefusedNamingTheRule() {
        byte[] payload = "{\"type\":\"logLine\",\"step\":3,\"level\":\"FINE\",\"text\":\"x\"}"
                .getBytes(StandardCharsets.UTF_8);

        InvalidValueException e = assertThrows(InvalidValueException.class, () -> json.decode(payload));
        assertTrue(e.getMessage().contains("SEVERE, WARNING or INFO"), e.getMessage());
    }

    @Test
    void aLineLongerThanTheCapIsRefused() {
        String text = "x".repeat(LogLine.MAX_TEXT + 1);

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new LogLine(1, "INFO", text));
        assertTrue(e.getMessage().contains("at most " + LogLine.MAX_TEXT), e.getMessage());
    }

    @Test
    void aNegativeStepIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new LogLine(-1, "INFO", "x"));
    }
}
