package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;
import robosim.protocol.MessageCodec.Format;

class WelcomeTest {
    private final MessageCodec json = new MessageCodec(Format.JSON);

    private static byte[] utf8(String text) {
        return text.getBytes(StandardCharsets.UTF_8);
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void theWorldsPropertiesAndTheRunsSeedCrossTheWireInOrder(Format format) throws FrameException {
        MessageCodec codec = new MessageCodec(format);
        Welcome welcome = Messages.welcome();

        Welcome decoded = (Welcome) codec.decode(codec.encode(welcome));

        assertEquals(List.of("cellSize", "goal.name"), List.copyOf(decoded.properties().keySet()));
        assertEquals("gold ✓", decoded.properties().get("goal.name"));
        assertEquals(-7_654_321_987L, decoded.seed());
    }

    @Test
    void aWelcomeWithoutPropertiesOrSeedFromAnOlderPeerHasNoneAndSeedZero() throws FrameException {
        Message m = json.decode(utf8("{\"type\":\"welcome\",\"name\":\"r1\",\"stepMs\":100,\"state\":null}"));

        assertEquals(new Welcome("r1", 100, null, Map.of(), 0), m);
    }

    @Test
    void theOldConstructorGivesNoPropertiesAndSeedZero() {
        Welcome w = new Welcome("r1", 100, null);

        assertEquals(Map.of(), w.properties());
        assertEquals(0, w.seed());
    }

    @Test
    void thePropertiesCannotBeChanged() {
        Map<String, String> given = new LinkedHashMap<>(Map.of("cellSize", "1000"));
        Welcome w = new Welcome("r1", 100, null, given, 1);
        given.put("other", "x");

        assertEquals(Map.of("cellSize", "1000"), w.properties());
        assertThrows(UnsupportedOperationException.class, () -> w.properties().put("x", "y"));
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "1cell", "_x", "cell size", "cellSize!", "ä",
        "a1234567890123456789012345678901234567890123456789012345678901234"})
    void aPropertyNameBreakingTheRuleIsAnInvalidValue(String name) {
        String escaped = name.replace("\\", "\\\\").replace("\"", "\\\"");
        byte[] payload = utf8("{\"type\":\"welcome\",\"name\":\"r1\",\"stepMs\":100,\"state\":null,"
                + "\"properties\":{\"" + escaped + "\":\"1\"},\"seed\":3}");

        InvalidValueException e = assertThrows(InvalidValueException.class, () -> json.decode(payload));

        assertTrue(e.getMessage().contains("was supplied for a property's name: a property's name is a letter"),
                e.getMessage());
    }

    @Test
    void aPropertyValueOverTheCapIsAnInvalidValue() {
        byte[] payload = utf8("{\"type\":\"welcome\",\"name\":\"r1\",\"stepMs\":100,\"state\":null,"
                + "\"properties\":{\"cellSize\":\"" + "9".repeat(Welcome.MAX_PROPERTY_VALUE + 1) + "\"}}");

        InvalidValueException e = assertThrows(InvalidValueException.class, () -> json.decode(payload));

        assertTrue(e.getMessage().contains("property cellSize has a value of 1025 characters: a property's value is "
                + "at most 1024 characters"), e.getMessage());
    }

    @Test
    void aNullPropertyValueIsAnInvalidValue() {
        byte[] payload = utf8("{\"type\":\"welcome\",\"name\":\"r1\",\"stepMs\":100,\"state\":null,"
                + "\"properties\":{\"cellSize\":null}}");

        InvalidValueException e = assertThrows(InvalidValueException.class, () -> json.decode(payload));

        assertTrue(e.getMessage().contains("property cellSize has no value"), e.getMessage());
    }

    @Test
    void moreThanTheCapOfPropertiesIsAnInvalidValue() {
        StringBuilder properties = new StringBuilder();
        for (int i = 0; i <= Welcome.MAX_PROPERTIES; i++) {
            properties.append(i == 0 ? "" : ",").append("\"p").append(i).append("\":\"\"");
        }
        byte[] payload = utf8("{\"type\":\"welcome\",\"name\":\"r1\",\"stepMs\":100,\"state\":null,"
                + "\"properties\":{" + properties + "}}");

        InvalidValueException e = assertThrows(InvalidValueException.class, () -> json.decode(payload));

        assertTrue(e.getMessage().contains("at most 256 world properties, got 257"), e.getMessage());
    }
}
