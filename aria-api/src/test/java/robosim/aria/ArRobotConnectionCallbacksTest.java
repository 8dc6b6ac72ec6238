package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.CapturedLog;
import robosim.protocol.RobotState;

/**
 * The connection callbacks fire once, at ARIA's moments (ArRobot.cpp: startStabilization,
 * finishedConnection, disconnect, dropConnection, failedConnect, the sync loop's exit). The welcome
 * is given by hand, as the hardware gives it when the Environment welcomes the robot.
 */
class ArRobotConnectionCallbacksTest {
    private final List<String> calls = new ArrayList<>();

    private void listen(ArRobot robot) {
        robot.addStabilizingCB(() -> calls.add("stabilizing"));
        robot.addConnectCB(() -> calls.add("connect"));
        robot.addFailedConnectCB(() -> calls.add("failed"));
        robot.addDisconnectNormallyCB(() -> calls.add("normally"));
        robot.addDisconnectOnErrorCB(() -> calls.add("error"));
        robot.addRunExitCB(() -> calls.add("runExit"));
    }

    private static RobotState at(long timeMs) {
        return new RobotState(timeMs / 100, timeMs, 0, 0, 0, 0, 0, 0, 0, false, 0);
    }

    @Test
    void theWelcomeStabilizesThenConnectsAtOnceWithTheDefaultStabilizingTime() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        listen(robot);
        robot.welcomed(at(0));
        assertEquals(List.of("stabilizing", "connect"), calls);
        assertFalse(robot.isStabilizing());
        assertEquals(0, robot.getStabilizingTime());
    }

    @Test
    void aStabilizingTimeHoldsTheConnectCallbacksUntilItHasPassed() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        listen(robot);
        robot.setStabilizingTime(250);
        robot.welcomed(at(0));
        assertEquals(List.of("stabilizing"), calls);
        assertTrue(robot.isStabilizing());
        robot.cycle(null, null, null); // 100 ms
        robot.cycle(null, null, null); // 200 ms
        assertEquals(List.of("stabilizing"), calls);
        robot.cycle(null, null, null); // 300 ms: past 250
        assertEquals(List.of("stabilizing", "connect"), calls);
        assertFalse(robot.isStabilizing());
        robot.cycle(null, null, null);
        assertEquals(2, calls.size());
    }

    @Test
    void aNegativeStabilizingTimeIsZeroAsInAria() {
        ArRobot robot = Cycles.p3dxRobot();
        robot.setStabilizingTime(-5);
        assertEquals(0, robot.getStabilizingTime());
    }

    @Test
    void disconnectRunsTheNormalCallbacksThenTheRunExitOnesOnce() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        listen(robot);
        robot.runAsync();
        robot.welcomed(at(0));
        calls.clear();
        assertTrue(robot.disconnect());
        assertEquals(List.of("normally", "runExit"), calls);
        assertTrue(robot.disconnect(), "ARIA's disconnect answers true when there is nothing to close");
        assertEquals(List.of("normally", "runExit"), calls);
    }

    @Test
    void aRobotThatNeverConnectedRunsNoDisconnectCallbacks() {
        ArRobot robot = Cycles.p3dxRobot();
        listen(robot);
        assertTrue(robot.disconnect());
        assertEquals(List.of(), calls);
    }

    @Test
    void dropConnectionRunsTheErrorCallbacksWithTheReasons() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        listen(robot);
        robot.runAsync();
        robot.welcomed(at(0));
        calls.clear();
        robot.dropConnection("the link broke", null);
        assertEquals(List.of("error", "runExit"), calls);
        assertEquals("the link broke", robot.getDropConnectionReason());
        assertEquals("the link broke", robot.getDropConnectionUserReason());
        robot.dropConnection("again", "again");
        robot.disconnect();
        assertEquals(List.of("error", "runExit"), calls, "the end is told once");
    }

    @Test
    void stopRunningWithoutDisconnectingRunsOnlyTheRunExitCallbacksOnce() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        listen(robot);
        robot.welcomed(at(0));
        calls.clear();
        robot.stopRunning(false);
        assertEquals(List.of(), calls, "the cycle was not started by run or runAsync");
        robot.runAsync();
        robot.stopRunning(false);
        robot.stopRunning(false);
        assertEquals(List.of("runExit"), calls);
    }

    @Test
    void firstGoesInFrontAndAnInvalidPositionIsRefusedWithALogLine() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        robot.addConnectCB(() -> calls.add("last"));
        robot.addConnectCB(() -> calls.add("first"), ArListPos.FIRST);
        try (CapturedLog log = new CapturedLog("robosim.aria")) {
            robot.addConnectCB(() -> calls.add("nowhere"), 7);
            assertTrue(log.lines().stream().anyMatch(l -> l.contains("addConnectCB") && l.contains("Invalid position")),
                    log.lines().toString());
        }
        Runnable removed = () -> calls.add("removed");
        robot.addConnectCB(removed);
        robot.remConnectCB(removed);
        robot.welcomed(at(0));
        assertEquals(List.of("first", "last"), calls);
    }

    @Test
    void theRunExitListIsACopyInOrder() {
        ArRobot robot = Cycles.p3dxRobot();
        Runnable a = () -> { };
        Runnable b = () -> { };
        robot.addRunExitCB(a);
        robot.addRunExitCB(b, ArListPos.FIRST);
        assertEquals(List.of(b, a), robot.getRunExitListCopy());
        robot.remRunExitCB(a);
        assertEquals(List.of(b), robot.getRunExitListCopy());
    }

    @Test
    void aFailedConnectRunsTheFailedCallbacksAndEndsTheWaitForConnectOrFail() throws Exception {
        // nothing listens on this port: the connection is refused at once
        int port;
        try (java.net.ServerSocket s = new java.net.ServerSocket(0)) {
            port = s.getLocalPort();
        }
        ArRobot robot = new ArRobot("r", "127.0.0.1", port, Cycles.p3dx());
        listen(robot);
        ArRobot.WaitState[] seen = new ArRobot.WaitState[1];
        Thread waiter = new Thread(() -> seen[0] = robot.waitForConnectOrConnFail(60_000));
        waiter.start();
        Thread.sleep(50);
        String before = System.getProperty(robosim.hw.HardwareOptions.CONNECT_TIMEOUT_PROPERTY);
        System.setProperty(robosim.hw.HardwareOptions.CONNECT_TIMEOUT_PROPERTY, "300");
        try {
            assertFalse(robot.blockingConnect());
        } finally {
            if (before == null) {
                System.clearProperty(robosim.hw.HardwareOptions.CONNECT_TIMEOUT_PROPERTY);
            } else {
                System.setProperty(robosim.hw.HardwareOptions.CONNECT_TIMEOUT_PROPERTY, before);
            }
        }
        waiter.join(10_000);
        assertEquals(ArRobot.WaitState.WAIT_FAILED_CONN, seen[0]);
        assertEquals(List.of("failed"), calls);
    }

    @Test
    void waitForConnectTimesOutAndIsWokenAsInAria() throws Exception {
        ArRobot robot = Cycles.p3dxRobot();
        assertEquals(ArRobot.WaitState.WAIT_TIMEDOUT, robot.waitForConnect(30));
        ArRobot.WaitState[] seen = new ArRobot.WaitState[1];
        Thread waiter = new Thread(() -> seen[0] = robot.waitForConnect(60_000));
        waiter.start();
        Thread.sleep(50);
        robot.wakeAllConnWaitingThreads();
        waiter.join(10_000);
        assertEquals(ArRobot.WaitState.WAIT_CONNECTED, seen[0], "ARIA's woken waitForConnect answers WAIT_CONNECTED");
    }

    @Test
    void asyncConnectIsRefusedUnlessTheCycleRuns() {
        ArRobot robot = Cycles.p3dxRobot();
        assertFalse(robot.asyncConnect());
    }

    @Test
    void waitForRunExitAnswersAtOnceWhenTheCycleIsNotRunning() {
        ArRobot robot = Cycles.p3dxRobot();
        assertEquals(ArRobot.WaitState.WAIT_RUN_EXIT, robot.waitForRunExit(1000));
    }

    @Test
    void theConnectionsTimesAreSimulated() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        robot.welcomed(at(700));
        assertEquals(700, robot.getConnectionOpenedTime().getTimeMs());
        robot.cycle(null, null, null);
        assertEquals(100, robot.getLastPacketTime().getTimeMs());
        assertEquals(8000, robot.getConnectionTimeoutTime());
        robot.setConnectionTimeoutTime(-3);
        assertEquals(0, robot.getConnectionTimeoutTime());
    }
}
