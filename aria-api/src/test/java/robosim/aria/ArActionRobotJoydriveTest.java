package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

/** ArActionRobotJoydrive.cpp's rules: the deadman, the dead zone, the stick as fractions of the maximums. */
class ArActionRobotJoydriveTest {
    private final ActionFixture f = new ActionFixture();
    private final ArActionRobotJoydrive joy = f.attach(new ArActionRobotJoydrive());

    @Test
    void withNoJoystickPacketTheDeadmanIsUpAndItWantsNothing() {
        f.at(0, 0, 0, 0);
        assertNull(ActionFixture.fire(joy));
    }

    @Test
    void withTheDeadmanHeldTheStickGivesFractionsOfTheRobotsMaximums() {
        f.at(0, 0, 0, 0);
        joy.handleJoystickPacket(1, 0, 0, 768, 512);
        ArActionDesired d = ActionFixture.fire(joy);
        assertEquals(0.5 * 0.5 * f.robot.getTransVelMax(), d.getVel(), 1e-9);
        assertEquals(1.0 * 0.5 * f.robot.getRotVelMax(), d.getRotVel(), 1e-9);
    }

    @Test
    void aStickWithinAThirdOfItsTravelStopsOnceWithoutTheDeadman() {
        ArActionRobotJoydrive free = f.attach(new ArActionRobotJoydrive("free", false));
        f.at(0, 0, 0, 0);
        free.handleJoystickPacket(0, 0, 600, 400, 1024);
        ArActionDesired d = ActionFixture.fire(free);
        assertEquals(0, d.getVel());
        assertEquals(1, d.getVelStrength());
        assertNull(ActionFixture.fire(free), "then nothing");
    }

    @Test
    void pullingBackWhileGoingForwardAsksForThreeTimesTheDeceleration() {
        f.at(0, 0, 0, 300);
        joy.handleJoystickPacket(1, 0, 512, 0, 1024);
        ArActionDesired d = ActionFixture.fire(joy);
        assertEquals(f.robot.getTransDecel() * 3, d.getTransDecel(), 1e-9);
        assertEquals(-f.robot.getTransVelMax(), d.getVel(), 1e-9);
    }
}
