package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Whether the motors are enabled travels in the state; a state that does not know leaves it out. */
class MotorsEnabledCodecTest {
    private static RobotState state(Boolean motors) {
        return new RobotState(3, 300, 1, 2, 3, 0, 0, 0, 0, false, 0).withMotorsEnabled(motors);
    }

    @ParameterizedTest
    @EnumSource(MessageCodec.Format.class)
    void theMotorsFlagRoundTrips(MessageCodec.Format format) throws FrameException {
        MessageCodec codec = new MessageCodec(format);
        for (Boolean motors : new Boolean[] {true, false, null}) {
            TimeStep decoded = (TimeStep) codec.decode(codec.encode(new TimeStep(3, 300, state(motors))));
            assertEquals(motors, decoded.state().motorsEnabled());
        }
    }

    @ParameterizedTest
    @EnumSource(value = MessageCodec.Format.class, names = "JSON")
    void aStateThatDoesNotKnowLeavesItOut(MessageCodec.Format format) throws FrameException {
        String json = new String(new MessageCodec(format).encode(new TimeStep(3, 300, state(null))),
                StandardCharsets.UTF_8);
        assertFalse(json.contains("motorsEnabled"), json);
        assertNull(state(null).motorsEnabled());
    }
}
