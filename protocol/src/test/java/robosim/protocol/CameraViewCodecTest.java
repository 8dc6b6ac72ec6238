package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.api.Test;

/** The camera's part of a robot's state, and the colour rule of a channel binding, on the wire. */
class CameraViewCodecTest {
    private static RobotState withCamera(CameraView camera) {
        RobotState s = Messages.state();
        return s.with(CameraView.PART, camera);
    }

    @ParameterizedTest
    @EnumSource(MessageCodec.Format.class)
    void theCameraViewRoundTrips(MessageCodec.Format format) throws FrameException {
        CameraView view = new CameraView(PtzModel.VCC4, 12.5, -3, 450,
                List.of(new ColorBlob(1, 300, 80, 61, 70, 89, 50, 72), new ColorBlob(4, 2, 0, 119, 0, 1, 119, 119)));
        MessageCodec codec = new MessageCodec(format);
        TimeStep back = (TimeStep) codec.decode(codec.encode(new TimeStep(1, 2, withCamera(view))));
        assertEquals(view, back.state().get(CameraView.PART));
    }

    @Test
    void aStateWithoutACameraLeavesItOutOfTheJson() throws FrameException {
        MessageCodec json = new MessageCodec(MessageCodec.Format.JSON);
        byte[] bytes = json.encode(new TimeStep(1, 2, withCamera(null)));
        assertTrue(!new String(bytes, StandardCharsets.UTF_8).contains("camera"));
        assertNull(((TimeStep) json.decode(bytes)).state().get(CameraView.PART));
    }

    @Test
    void aChannelOutsideOneToThirtyTwoOrABadColourIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Command.BindChannel(33, "red"));
        assertTrue(e.getMessage().contains("33 was supplied for an ACTS channel: channels are 1 to 32"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new Command.BindChannel(1, "#ff00"));
        assertTrue(e.getMessage().contains("'#ff00' is not a colour"), e.getMessage());
        assertEquals("#ff0000", new Command.BindChannel(1, " Red ").color());
    }
}
