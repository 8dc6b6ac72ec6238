package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.RobotState;
import robosim.protocol.RobotStates;

/** ARIA's rule for the turn away from pressed bumpers (ArActionBumpers.cpp's findDegreesToTurn). */
class ArActionBumpersTest {
    @Test
    void theMiddleBumperOfFiveTurnsByHalfTheRange() {
        // bumper 2 of 5 stands for 2 · 27 + 13.5 − 67.5 = 0°: turn 67.5 − 0
        assertEquals(67.5, ArActionBumpers.degreesToTurn(1 << 3, 5), 1e-9);
    }

    @Test
    void theRightmostBumperTurnsAShortWayTheOtherWay() {
        // bumper 0 stands for −54°: turn −(67.5 − 54)
        assertEquals(-13.5, ArActionBumpers.degreesToTurn(1 << 1, 5), 1e-9);
    }

    @Test
    void severalPressedBumpersStandForTheMeanOfTheirAngles() {
        // bumpers 3 and 4 stand for 27° and 54°, mean 40.5°: turn 67.5 − 40.5
        assertEquals(27, ArActionBumpers.degreesToTurn((1 << 4) | (1 << 5), 5), 1e-9);
    }

    /** One cycle of a robot at the origin driving at a velocity, with these contact sectors pressed. */
    private static void cycle(ArRobot robot, long timeMs, double vel, int sectors) {
        robot.responded(new RobotSensorResponse(RobotStates.of(robot.getCounter() + 1, timeMs, 0, 0, 0, vel, 0, vel,
                vel, false, new int[0], 0, new int[0], null, List.of(), List.of(), sectors)));
    }

    @Test
    void activatingItAgainForgetsABackOffUnderWay() {
        ArRobot robot = new ArRobot("r", "127.0.0.1", 5000, "p3dx"); // front and rear rings
        ArActionBumpers bumpers = new ArActionBumpers();
        bumpers.setRobot(robot);
        cycle(robot, 100, 200, 1); // driving into something ahead
        ArActionDesired backing = bumpers.fire(new ArActionDesired());
        assertEquals(-100, backing.getVel(), "backs off at ARIA's 100 mm/s");
        assertSame(backing, bumpers.getDesired());
        cycle(robot, 200, -100, 0);
        assertEquals(-100, bumpers.fire(new ArActionDesired()).getVel(), "for its back-off time");

        bumpers.deactivate();
        bumpers.activate();
        assertNull(bumpers.fire(new ArActionDesired()), "nothing pressed: the back-off is forgotten");
    }
}
