package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** ARIA's done and stopped thresholds (ArRobot.cpp's isMoveDone, isHeadingDone, isStopped): settable, 0 means the robot's own. */
class ArRobotDoneTest {
    private final ArRobot robot = Cycles.p3dxRobot();

    @Test
    void aMoveIsDoneWithinTheMoveDoneDistanceSet() {
        Cycles.cycle(robot, 100, 0, 0, 0);
        robot.move(1000);
        Cycles.cycle(robot, 200, 950, 0, 0);

        assertEquals(40, robot.getMoveDoneDist());
        assertFalse(robot.isMoveDone(), "950 of 1000 is not within ARIA's 40 mm");
        robot.setMoveDoneDist(60);
        assertTrue(robot.isMoveDone());
        assertFalse(robot.isMoveDone(10), "a delta given wins over the one set");
    }

    @Test
    void aHeadingIsDoneWithinTheHeadingDoneDifferenceSet() {
        Cycles.cycle(robot, 100, 0, 0, 0);
        robot.setHeading(90);
        Cycles.cycle(robot, 200, 0, 0, 85);

        assertEquals(3, robot.getHeadingDoneDiff());
        assertFalse(robot.isHeadingDone());
        robot.setHeadingDoneDiff(6);
        assertTrue(robot.isHeadingDone());
        assertTrue(robot.isHeadingDone(0.0005), "below 0.001 means the robot's own, as in ARIA");
    }

    @Test
    void stoppedIsAtMostTheStoppedVelocitiesGivenOrSet() {
        Cycles.cycleMoving(robot, 100, 3, 0.5);
        assertTrue(robot.isStopped(), "within ARIA's 4 mm/s and 1 deg/s");

        Cycles.cycleMoving(robot, 200, 10, 0.5);
        assertFalse(robot.isStopped());
        assertTrue(robot.isStopped(10, 0), "10 mm/s given; the rotational threshold the robot's own");
        robot.setStoppedVels(12, 2);
        assertTrue(robot.isStopped());
    }
}
