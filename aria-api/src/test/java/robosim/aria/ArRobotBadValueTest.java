package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** A motion call with a value no command can hold throws in the caller and leaves the robot as it was. */
class ArRobotBadValueTest {
    private final ArRobot robot = new ArRobot("r", "127.0.0.1", 5000, "p3dx");

    @Test
    void aNonFiniteLimitIsRefusedAndTheLimitStays() {
        double before = robot.getMaxTransVel();

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> robot.setMaxTransVel(Double.NaN));

        assertEquals("NaN was supplied for maxVel: it must be a finite number", e.getMessage());
        assertEquals(before, robot.getMaxTransVel());
    }

    @Test
    void aNonFiniteMoveIsRefusedAndNoMoveStarts() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> robot.move(Double.POSITIVE_INFINITY));

        assertEquals("Infinity was supplied for distance: it must be a finite number", e.getMessage());
        assertTrue(robot.isMoveDone());
    }

    @Test
    void aNonFiniteHeadingIsRefusedAndNoTurnStarts() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> robot.setHeading(Double.NaN));

        assertEquals("NaN was supplied for heading: it must be a finite number", e.getMessage());
        assertTrue(robot.isHeadingDone());
    }
}
