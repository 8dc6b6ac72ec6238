package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.ValueSource;
import robosim.protocol.MessageCodec.Format;

/** The gripper's command and state, and the world's objects, on the wire and in recordings. */
class GripperMessagesTest {
    private static Message roundTrip(Format format, Message message) throws FrameException {
        MessageCodec codec = new MessageCodec(format);
        return codec.decode(codec.encode(message));
    }

    private static RobotState state(GripperState g) {
        return new RobotState(3, 300, 1, 2, 3, 0, 0, 0, 0, false, 0).with(GripperState.PART, g);
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void aStateCarriesTheGripper(Format format) throws FrameException {
        GripperState g = new GripperState(GripperState.PADDLES_OPEN_CLEAR | GripperState.INNER_BEAM, 10, 0.6465,
                1, 0);
        TimeStep decoded = (TimeStep) roundTrip(format, new TimeStep(3, 300, state(g)));
        assertEquals(g, decoded.state().get(GripperState.PART));
    }

    @Test
    void aStateWithoutAGripperLeavesItOffTheWire() {
        String json = new String(new MessageCodec(Format.JSON).encode(new TimeStep(3, 300, state(null))),
                StandardCharsets.UTF_8);
        assertFalse(json.contains("gripper"), json);
    }

    @ParameterizedTest
    @ValueSource(ints = {0, 9, 14, 18, 33})
    void aGripperCodeAriaDoesNotHaveIsRefused(int op) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Command.Gripper(op));
        assertTrue(e.getMessage().contains(op + " was supplied for the gripper command"), e.getMessage());
    }

    @Test
    void aGraspTimeBeyondAByteIsRefused() {
        assertThrows(IllegalArgumentException.class,
                () -> new Command.Gripper(Command.Gripper.GRIP_PRESSURE, 256));
    }

    @Test
    void aBadGripperCodeOnTheWireIsRefusedAsAFrameError() {
        byte[] payload = ("{\"type\":\"robotRequests\",\"step\":5,\"commands\":[{\"cmd\":\"gripper\",\"op\":99,"
                + "\"value\":0}]}").getBytes(StandardCharsets.UTF_8);
        FrameException e = assertThrows(FrameException.class, () -> new MessageCodec(Format.JSON).decode(payload));
        assertTrue(e.getMessage().contains("99"), e.getMessage());
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void snapshotsAndDescriptionsCarryTheObjects(Format format) throws FrameException {
        Snapshot s = new Snapshot(4, 400, List.of()).withObjects(
                List.of(new Snapshot.ObjectView(1200.5, 800, "r1", true), new Snapshot.ObjectView(10, 20, null, false)));
        assertEquals(s.objects(), ((Snapshot) roundTrip(format, s)).objects());
        WorldDescription w = new WorldDescription("w", 100, 50, 100, List.of(), List.of(), List.of())
                .withObjects(List.of(new WorldDescription.WorldObject("puck", 10, 20, 38, "red"),
                        new WorldDescription.WorldObject("puck", 30, 20, 38, null)));
        assertEquals(w.objects(), ((WorldDescription) roundTrip(format, w)).objects());
    }

    @Test
    void recordingsFromBeforeObjectsReadAsNone() throws FrameException {
        MessageCodec json = new MessageCodec(Format.JSON);
        Snapshot s = (Snapshot) json.decode(("{\"type\":\"frame\",\"step\":1,\"timeMs\":100,\"robots\":[]}")
                .getBytes(StandardCharsets.UTF_8));
        assertEquals(List.of(), s.objects());
        WorldDescription w = (WorldDescription) json.decode(("{\"type\":\"world\",\"name\":\"w\",\"width\":100.0,"
                + "\"height\":50.0,\"stepMs\":100,\"obstacles\":[],\"robots\":[],\"heat\":[]}")
                .getBytes(StandardCharsets.UTF_8));
        assertEquals(List.of(), w.objects());
    }

    @Test
    void parametersWithoutAGripperLeaveItOffTheWireAndWithOneCarryIt() throws FrameException {
        MessageCodec json = new MessageCodec(Format.JSON);
        RobotHello plain = Messages.robotHello();
        String text = new String(json.encode(plain), StandardCharsets.UTF_8);
        assertFalse(text.contains("hasGripper"), text);
        assertFalse(((RobotHello) json.decode(text.getBytes(StandardCharsets.UTF_8))).parameters().hasGripper());
        RobotHello gripper = new RobotHello(plain.name(), plain.robotType(), plain.parameters().withGripper(true),
                plain.token());
        assertEquals(gripper, roundTrip(Format.JSON, gripper));
        assertEquals(gripper, roundTrip(Format.SMILE, gripper));
    }
}
