package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.RobotState;

/** ARIA's areMotorsEnabled answers from the latest state's flag, as ARIA's reads the latest SIP's. */
class ArRobotMotorsTest {
    private final ArRobot robot = Cycles.p3dxRobot();

    private void cycle(Boolean motors) {
        robot.responded(new RobotSensorResponse(new RobotState(robot.getCounter() + 1, 100 * robot.getCounter(), 0, 0,
                0, 0, 0, 0, 0, false, 0).withMotorsEnabled(motors)));
    }

    @Test
    void beforeTheRobotHasSaidTheMotorsAreNotEnabled() {
        assertFalse(robot.areMotorsEnabled());
        cycle(null);
        assertFalse(robot.areMotorsEnabled());
    }

    @Test
    void theAnswerFollowsTheState() {
        cycle(true);
        assertTrue(robot.areMotorsEnabled());
        cycle(false);
        assertFalse(robot.areMotorsEnabled());
    }

    @Test
    void aRequestChangesNothingUntilTheNextCycleReportsIt() {
        cycle(false);
        robot.enableMotors();
        assertFalse(robot.areMotorsEnabled(), "ARIA's flag changes with the next SIP, not with the request");
        cycle(true);
        robot.disableMotors();
        assertTrue(robot.areMotorsEnabled());
    }
}
