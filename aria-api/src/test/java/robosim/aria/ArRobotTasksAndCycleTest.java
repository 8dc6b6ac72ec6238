package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.CapturedLog;

/** Task lookups and logs, loopOnce and the cycle's settings, as ARIA's ArRobot has them. */
class ArRobotTasksAndCycleTest {
    @Test
    void findTaskSearchesEveryTaskAndFindUserTaskOnlyTheUserOnes() {
        ArRobot robot = Cycles.p3dxRobot();
        Runnable sensor = () -> { };
        Runnable user = () -> { };
        robot.addSensorInterpTask("sense", 10, sensor);
        robot.addUserTask("plan", 5, user);
        assertEquals("sense", robot.findTask("sense").getName());
        assertEquals(10, robot.findTask("sense").getPosition());
        assertSame(user, robot.findTask("plan").getFunctor());
        assertEquals("plan", robot.findTask(user).getName());
        assertNull(robot.findUserTask("sense"));
        assertEquals("plan", robot.findUserTask(user).getName());
        assertNull(robot.findTask("nothing"));
        assertTrue(robot.remUserTask(user));
        assertNull(robot.findUserTask("plan"));
        assertTrue(robot.remSensorInterpTask(sensor));
        assertFalse(robot.remSensorInterpTask(sensor));
    }

    @Test
    void theTaskLogsListTheTasksInRunningOrder() {
        ArRobot robot = Cycles.p3dxRobot();
        robot.addUserTask("low", 1, () -> { });
        robot.addUserTask("high", 9, () -> { });
        robot.addSensorInterpTask("sense", 0, () -> { });
        try (CapturedLog log = new CapturedLog("robosim.aria")) {
            robot.logUserTasks();
            String user = String.join("\n", log.lines());
            assertTrue(user.indexOf("high") < user.indexOf("low") && user.indexOf("high") > 0, user);
            assertFalse(user.contains("sense"), user);
            log.clear();
            robot.logAllTasks();
            String all = String.join("\n", log.lines());
            assertTrue(all.contains("sense") && all.contains("high"), all);
        }
    }

    @Test
    void loopOnceRunsTheTasksOnceAndCountsACycle() {
        ArRobot robot = Cycles.p3dxRobot();
        List<String> ran = new ArrayList<>();
        robot.addSensorInterpTask("sense", 0, () -> ran.add("sense"));
        robot.addUserTask("user", 0, () -> ran.add("user"));
        robot.loopOnce();
        assertEquals(List.of("sense", "user"), ran);
        assertEquals(1, robot.getCounter());
        robot.incCounter();
        assertEquals(2, robot.getCounter());
    }

    @Test
    void theCycleIsTheStepAndStaysChained() {
        ArRobot robot = Cycles.p3dxRobot();
        assertEquals(robot.getStepMs(), robot.getCycleTime());
        try (CapturedLog log = new CapturedLog("robosim.aria")) {
            robot.setCycleTime(50);
            assertTrue(log.lines().stream().anyMatch(l -> l.contains("setCycleTime(50)")), log.lines().toString());
        }
        assertEquals(robot.getStepMs(), robot.getCycleTime());
        robot.setCycleChained(false);
        assertTrue(robot.isCycleChained());
    }

    @Test
    void aSlowCycleIsLoggedUnlessTheCycleSaysNot() {
        ArRobot robot = Cycles.p3dxRobot();
        assertEquals(250, robot.getCycleWarningTime());
        robot.setCycleWarningTime(5);
        boolean[] quiet = {false};
        robot.addUserTask("slow", 0, () -> {
            if (quiet[0]) {
                robot.setNoTimeWarningThisCycle(true);
            }
            try {
                Thread.sleep(30);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        try (CapturedLog log = new CapturedLog("robosim.aria")) {
            Cycles.cycle(robot, 100, 0, 0, 0);
            assertTrue(log.lines().stream().anyMatch(l -> l.contains("Cycle took")), log.lines().toString());
            log.clear();
            quiet[0] = true;
            Cycles.cycle(robot, 200, 0, 0, 0);
            assertFalse(log.lines().stream().anyMatch(l -> l.contains("Cycle took")), log.lines().toString());
            assertFalse(robot.getNoTimeWarningThisCycle(), "cleared after the cycle");
        }
    }

    @Test
    void thePacketCountsAreThoseOfTheLastWholeSecond() {
        ArRobot robot = Cycles.p3dxRobot();
        for (long t = 100; t <= 1500; t += 100) {
            Cycles.cycle(robot, t, 0, 0, 0);
        }
        assertEquals(9, robot.getMotorPacCount(), "100 ms to 900 ms");
        assertEquals(0, robot.getSonarPacCount(), "no sonar readings came");
        Cycles.cycle(robot, 3100, 0, 0, 0);
        assertEquals(0, robot.getMotorPacCount(), "no state came in the second before");
    }

    @Test
    void theActionCallsLogAndAnswerAsAriasDo() {
        ArRobot robot = Cycles.p3dxRobot();
        ArActionStop stop = new ArActionStop("stop here");
        robot.addAction(stop, 50);
        stop.deactivate();
        try (CapturedLog log = new CapturedLog("robosim.aria")) {
            robot.logActions();
            assertFalse(String.join("\n", log.lines()).contains("stop here"), log.lines().toString());
            log.clear();
            robot.logActions(true);
            String all = String.join("\n", log.lines());
            assertTrue(all.contains("Priority 50") && all.contains("stop here"), all);
        }
        assertEquals(robot.getActionList(), robot.getActionMap());
        assertFalse(robot.getLogActions());
        robot.setLogActions(true);
        assertTrue(robot.getLogActions());
    }
}
