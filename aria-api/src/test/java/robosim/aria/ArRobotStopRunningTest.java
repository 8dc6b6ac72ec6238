package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** stopRunning stops the robot's cycle (ARIA's ArRobot::stopRunning); the battery is constant. */
class ArRobotStopRunningTest {
    @Test
    void afterStopRunningNoTaskRunsAndTheCounterStops() {
        ArRobot robot = Cycles.p3dxRobot();
        AtomicInteger runs = new AtomicInteger();
        robot.addUserTask("count", 0, runs::incrementAndGet);
        Cycles.cycle(robot, 100, 0, 0, 0);
        robot.stopRunning(false);
        Cycles.cycle(robot, 200, 10, 0, 0);
        assertEquals(1, robot.getCounter());
        assertEquals(1, runs.get());
        assertFalse(robot.isRunning());
        robot.runAsync();
        Cycles.cycle(robot, 300, 20, 0, 0);
        assertEquals(2, robot.getCounter());
        assertEquals(2, runs.get());
    }
}
