package robosim.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;

/** What each control of the window sends to the robot, and what the status line then says. */
class RemoteControlTest {
    private final Fixtures.Recorder robot = new Fixtures.Recorder(Fixtures.robot(1200, 200));
    private final RemoteControl control = new RemoteControl(robot);

    @Test
    void theForwardButtonDrivesAtTheSliderSpeedUntilStop() {
        assertEquals("sent: vel 300 mm/s, rotVel 0 deg/s", control.button(RemoteControl.Button.FORWARD));
        assertEquals("sent: stop", control.button(RemoteControl.Button.STOP));
        assertEquals(List.of("drive 300 0", "stop"), robot.calls);
    }

    @Test
    void theTurnButtonsTurnOnTheSpot() {
        control.button(RemoteControl.Button.LEFT);
        control.button(RemoteControl.Button.RIGHT);
        control.button(RemoteControl.Button.BACK);
        assertEquals(List.of("drive 0 30", "drive 0 -30", "drive -300 0"), robot.calls);
    }

    @Test
    void movingASliderWhileDrivingResendsAtTheNewSpeed() {
        control.button(RemoteControl.Button.FORWARD);
        assertEquals("sent: vel 500 mm/s, rotVel 0 deg/s", control.setVel(500));
        assertEquals(List.of("drive 300 0", "drive 500 0"), robot.calls);
    }

    @Test
    void movingASliderWhileStoppedSendsNothing() {
        assertNull(control.setRotVel(90));
        assertEquals(90, control.rotVel());
        assertEquals(List.of(), robot.calls);
    }

    @Test
    void aSliderValuePastTheRobotsLimitIsClampedToIt() {
        control.setVel(5000);
        assertEquals(1200, control.vel());
    }

    @Test
    void holdingUpDrivesAndReleasingItStopsAfterTheGraceTime() {
        assertEquals("sent: vel 300 mm/s, rotVel 0 deg/s", control.keyPressed(KeyDrive.Key.FORWARD, 0));
        control.keyReleased(KeyDrive.Key.FORWARD, 500);
        assertNull(control.tick(550));
        assertEquals("sent: stop (keys released)", control.tick(500 + KeyDrive.RELEASE_GRACE_MS));
        assertEquals(List.of("drive 300 0", "stop"), robot.calls);
    }

    @Test
    void losingTheKeyboardWhileAKeyIsHeldStops() {
        control.keyPressed(KeyDrive.Key.LEFT, 0);
        assertEquals("sent: stop (the window lost the keyboard)", control.keysLost());
        assertNull(control.keysLost(), "nothing held any more");
        assertEquals(List.of("drive 0 30", "stop"), robot.calls);
    }

    @Test
    void theMoveFieldSendsAMoveAndABadValueSendsNothing() {
        assertEquals("sent: move -250 mm", control.move(" -250 "));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> control.move("far"));
        assertEquals("'far' was supplied for move distance: it is a distance in mm, e.g. 500, or -250 to back up",
                e.getMessage());
        assertEquals(List.of("move -250.0"), robot.calls);
    }

    @Test
    void theHeadingFieldSendsSetHeading() {
        assertEquals("sent: heading -90.0°", control.heading("-90"));
        assertEquals(List.of("heading -90.0"), robot.calls);
    }

    @Test
    void aSensorTheRobotLacksSaysWhy() {
        assertEquals("sent: laser on", control.laser(true));
        assertEquals("heat: no heat sensor here", control.heat(true));
        assertEquals("sent: sonar off", control.sonar(false));
        assertEquals(List.of("laser true", "heat true", "sonar false"), robot.calls);
    }

    @Test
    void theSendBoxSendsToAGroup() {
        assertEquals("sent: message to group scouts", control.send(MessageDraft.To.GROUP, "scouts", "meet at the door"));
        assertEquals(List.of("send group scouts: meet at the door"), robot.calls);
    }
}
