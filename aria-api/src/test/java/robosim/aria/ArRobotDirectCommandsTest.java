package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;

/**
 * ArRobot's direct commands that the other tests leave out: the wheel velocities, the rotational
 * limit, the sonars, and how long a direct command keeps its channels from the actions (ARIA's
 * {@code setDirectMotionPrecedenceTime}).
 */
class ArRobotDirectCommandsTest {
    private final ConnectedRobot robot = new ConnectedRobot("p3dx");

    @Test
    void setVel2SendsTheWheelVelocitiesAndTakesBothChannelsFromTheActions() {
        robot.cycleWheels(0, 0, 0, 0, 0);
        assertFalse(robot.isDirectMotion());
        robot.setVel2(100, 200);
        assertEquals(new Command.SetVel2(100, 200), robot.last());
        assertTrue(robot.isDirectMotion(), "translation and rotation both held");
        assertThrows(IllegalArgumentException.class, () -> robot.setVel2(Double.NaN, 0));
    }

    @Test
    void theWheelVelocitiesAreTheLatestStates() {
        assertEquals(0, robot.getLeftVel());
        robot.cycleWheels(0, 0, 0, 150, 250);
        assertEquals(150, robot.getLeftVel());
        assertEquals(250, robot.getRightVel());
        assertEquals(200, robot.getVel(), "the robot's velocity is their mean");
    }

    @Test
    void setMaxRotVelIsSentAndAnsweredWithinTheParameterFilesMaximum() {
        double fileMax = robot.getParameters().maxRVelocity();
        assertEquals(fileMax, robot.getMaxRotVel(), "the file's maximum at first");
        robot.setMaxRotVel(40);
        assertEquals(new Command.SetMaxRotVel(40), robot.last());
        assertEquals(40, robot.getMaxRotVel());
        robot.setMaxRotVel(fileMax + 100);
        assertEquals(fileMax, robot.getMaxRotVel(), "capped at the file's maximum");
        robot.setMaxRotVel(-5);
        assertEquals(0, robot.getMaxRotVel(), "never below 0");
    }

    @Test
    void theSonarsAreOnAtFirstAndEachSwitchIsSent() {
        assertTrue(robot.areSonarsEnabled());
        robot.disableSonar();
        assertFalse(robot.areSonarsEnabled());
        robot.enableSonar();
        assertTrue(robot.areSonarsEnabled());
        assertEquals(List.of(new Command.SetSonar(false), new Command.SetSonar(true)), robot.sent);
    }

    @Test
    void aDirectCommandHoldsItsChannelUntilClearedOrForThePrecedenceTime() {
        assertEquals(0, robot.getDirectMotionPrecedenceTime(), "ARIA's default: until cleared");
        robot.cycleWheels(0, 0, 0, 0, 0); // time 100
        robot.setVel(100);
        robot.cycleWheels(0, 0, 0, 0, 0); // time 200
        robot.cycleWheels(0, 0, 0, 0, 0); // time 300
        assertTrue(robot.isDirectMotion());
        robot.clearDirectMotion();
        assertFalse(robot.isDirectMotion());

        robot.setDirectMotionPrecedenceTime(150);
        assertEquals(150, robot.getDirectMotionPrecedenceTime());
        robot.setVel(100); // at time 300
        robot.cycleWheels(0, 0, 0, 0, 0); // time 400
        assertTrue(robot.isDirectMotion(), "100 ms after: still held");
        robot.cycleWheels(0, 0, 0, 0, 0); // time 500
        assertFalse(robot.isDirectMotion(), "200 ms after: the actions have it again");
        robot.setDirectMotionPrecedenceTime(-10);
        assertEquals(0, robot.getDirectMotionPrecedenceTime(), "a negative time means until cleared");
    }
}
