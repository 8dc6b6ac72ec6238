package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** ARIA's virtual odometers: each cycle adds the straight line and the absolute turn since the last one. */
class ArRobotOdometerTest {
    private final ArRobot robot = Cycles.p3dxRobot();

    @Test
    void theOdometerAddsEachCyclesStraightLineAndTurnWhateverTheDirection() {
        Cycles.cycle(robot, 100, 0, 0, 0);
        Cycles.cycle(robot, 200, 300, 400, 10);
        Cycles.cycle(robot, 300, 0, 0, -20);
        Cycles.cycle(robot, 2300, 0, 0, 170);
        Cycles.cycle(robot, 2400, 0, 0, -170);

        assertEquals(1000, robot.getOdometerDistance(), 1e-9);
        // 10, 30, then -20 to 170 the short way (170, not 190), then 170 to -170 across 180 (20)
        assertEquals(10 + 30 + 170 + 20, robot.getOdometerDegrees(), 1e-9);
        assertEquals(2, robot.getOdometerTime());
    }

    @Test
    void theTripOdometerCountsFromItsResetAndTheOdometerGoesOn() {
        Cycles.cycle(robot, 100, 0, 0, 0);
        Cycles.cycle(robot, 200, 0, 500, 90);
        robot.resetTripOdometer();
        Cycles.cycle(robot, 1300, 0, 800, 45);

        assertEquals(300, robot.getTripOdometerDistance(), 1e-9);
        assertEquals(45, robot.getTripOdometerDegrees(), 1e-9);
        assertEquals(1, robot.getTripOdometerTime());
        assertEquals(800, robot.getOdometerDistance(), 1e-9);
        assertEquals(135, robot.getOdometerDegrees(), 1e-9);
    }

    @Test
    void beforeAnyCycleEveryOdometerIsNought() {
        assertEquals(0, robot.getOdometerDistance());
        assertEquals(0, robot.getOdometerDegrees());
        assertEquals(0, robot.getOdometerTime());
        assertEquals(0, robot.getTripOdometerDistance());
    }
}
