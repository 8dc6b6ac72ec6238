package robosim.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import org.junit.jupiter.api.Test;

/** With a target that drives by a keydrive action, each arrow-key press goes to the action; releases do nothing. */
class RemoteControlKeydriveTest {
    /** A recorder whose keys feed a keydrive action. */
    private static final class KeydriveRecorder extends Fixtures.Recorder {
        KeydriveRecorder() {
            super(Fixtures.robot(1500, 300));
        }

        @Override
        public boolean keydrive() {
            return true;
        }

        @Override
        public void keydrive(KeyDrive.Key key) {
            calls.add("keydrive " + key);
        }
    }

    private final KeydriveRecorder target = new KeydriveRecorder();
    private final RemoteControl control = new RemoteControl(target);

    @Test
    void eachPressIncludingAutoRepeatGoesToTheKeydriveAction() {
        assertEquals(true, control.keydrive());
        assertEquals("sent: keydrive forward", control.keyPressed(KeyDrive.Key.FORWARD, 0));
        assertEquals("sent: keydrive forward", control.keyPressed(KeyDrive.Key.FORWARD, 30));
        assertEquals("sent: keydrive left", control.keyPressed(KeyDrive.Key.LEFT, 60));
        assertEquals(List.of("keydrive FORWARD", "keydrive FORWARD", "keydrive LEFT"), target.calls);
    }

    @Test
    void releasingAKeyDoesNotStopTheRobot() {
        control.keyPressed(KeyDrive.Key.FORWARD, 0);
        control.keyReleased(KeyDrive.Key.FORWARD, 10);
        assertNull(control.tick(1000));
        assertNull(control.keysLost());
        assertEquals(List.of("keydrive FORWARD"), target.calls);
    }

    @Test
    void theStopButtonStillStops() {
        control.keyPressed(KeyDrive.Key.FORWARD, 0);
        assertEquals("sent: stop", control.button(RemoteControl.Button.STOP));
        assertEquals(List.of("keydrive FORWARD", "stop"), target.calls);
    }
}
