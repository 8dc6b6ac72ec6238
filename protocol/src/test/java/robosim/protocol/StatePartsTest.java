package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.HashSet;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The parts of a robot's state: one registry, each part a field of the state on the wire. */
class StatePartsTest {
    private static final MessageCodec JSON = new MessageCodec(MessageCodec.Format.JSON);

    private static RobotState bare() {
        return new RobotState(3, 300, 1, 2, 3, 0, 0, 0, 0, false, 0);
    }

    @Test
    void theRandomStatesOfTheCodecTestsDrawEveryRegisteredPart() {
        RandomMessages random = new RandomMessages(new Random(7));
        Set<String> drawn = new HashSet<>();
        for (int i = 0; i < 200; i++) {
            RobotState s = random.state();
            for (StatePart<?> part : StateParts.ALL) {
                if (s.parts().get(part) != null) {
                    drawn.add(part.name());
                }
            }
        }
        drawn.add(GripperState.PART.name()); // drawn by GripperMessagesTest
        drawn.add(CameraView.PART.name()); // drawn by CameraViewCodecTest
        for (StatePart<?> part : StateParts.ALL) {
            assertTrue(drawn.contains(part.name()), part.name() + " is registered but RandomMessages.state() never draws it");
        }
    }

    @Test
    void aPartIsAFieldNamedAfterItsKeyAndAbsentIsNotWritten() throws FrameException {
        RobotState s = bare().with(BatteryReading.PART, new BatteryReading(12.5, 80));
        String json = new String(JSON.encode(new TimeStep(4, 400, s)), StandardCharsets.UTF_8);
        assertTrue(json.contains("\"battery\":{\"volts\":12.5,\"stateOfCharge\":80.0}"), json);
        assertTrue(!json.contains("sonar") && !json.contains("laser"), json);
        RobotState back = ((TimeStep) JSON.decode(json.getBytes(StandardCharsets.UTF_8))).state();
        assertEquals(new BatteryReading(12.5, 80), back.get(BatteryReading.PART));
        assertSame(SonarReading.OFF, back.get(SonarReading.PART), "an absent sonar reads as off");
        assertNull(back.get(HeatReading.PART));
    }

    @Test
    void aFieldThatNamesNoPartIsRefusedAndANullPartIsAbsent() throws FrameException {
        String json = new String(JSON.encode(new TimeStep(4, 400, bare())), StandardCharsets.UTF_8);
        String unknown = json.replace("\"stalled\"", "\"compass\":90,\"stalled\"");
        FrameException e = assertThrows(FrameException.class,
                () -> JSON.decode(unknown.getBytes(StandardCharsets.UTF_8)));
        assertTrue(e.getMessage().contains("compass"), e.getMessage());
        String nullPart = json.replace("\"stalled\"", "\"battery\":null,\"stalled\"");
        assertNull(((TimeStep) JSON.decode(nullPart.getBytes(StandardCharsets.UTF_8))).state().get(BatteryReading.PART));
    }

    @Test
    void aPartThatBreaksItsRuleIsRefusedNamingIt() {
        String json = new String(JSON.encode(new TimeStep(4, 400, bare())), StandardCharsets.UTF_8)
                .replace("\"stalled\"", "\"battery\":{\"volts\":-3,\"stateOfCharge\":50},\"stalled\"");
        InvalidValueException e = assertThrows(InvalidValueException.class,
                () -> JSON.decode(json.getBytes(StandardCharsets.UTF_8)));
        assertTrue(e.getMessage().contains("-3.0 was supplied for the battery's volts"), e.getMessage());
    }

    @Test
    void aPartOutsideTheRegistryCannotBeHeld() {
        StatePart<String> stray = StatePart.of("stray", String.class);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> StateParts.NONE.with(stray, "x"));
        assertEquals("state part stray is not registered in StateParts.ALL", e.getMessage());
        assertEquals(StateParts.ALL.size(), StateParts.ALL.stream().map(StatePart::name).distinct().count());
    }
}
