package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import robosim.protocol.CapturedLog;
import robosim.protocol.Command;
import robosim.protocol.RobotParameters;

/**
 * ARIA's absolute maxima (ArRobot.cpp, setAbsoluteMaxTransVel and its kin): refused at 0 or less
 * with a log line, capped at the top with a log line, pulling the limits under them down; and the
 * negative and lateral limits of a robot without lateral motion.
 */
class ArRobotAbsoluteMaximaTest {
    @Test
    void theMaximaStartAtWhatTheEnvironmentDrives() {
        ArRobot robot = Cycles.p3dxRobot();
        RobotParameters p = robot.getParameters();
        assertEquals(p.maxVelocity(), robot.getAbsoluteMaxTransVel());
        assertEquals(-p.maxVelocity(), robot.getAbsoluteMaxTransNegVel());
        assertEquals(-p.maxVelocity(), robot.getTransNegVelMax());
        assertEquals(p.maxRVelocity(), robot.getAbsoluteMaxRotVel());
        assertEquals(RobotParameters.MAX_ACCELERATION, robot.getAbsoluteMaxTransAccel());
        assertEquals(RobotParameters.MAX_ACCELERATION, robot.getAbsoluteMaxTransDecel());
        assertEquals(RobotParameters.MAX_ACCELERATION, robot.getAbsoluteMaxRotAccel());
        assertEquals(RobotParameters.MAX_ACCELERATION, robot.getAbsoluteMaxRotDecel());
        assertEquals(0, robot.getAbsoluteMaxLatVel());
        assertEquals(0, robot.getAbsoluteMaxLatAccel());
        assertEquals(0, robot.getAbsoluteMaxLatDecel());
        assertFalse(robot.hasLatVel());
        assertTrue(robot.hasSettableVelMaxes());
        assertTrue(robot.hasSettableAccsDecs());
    }

    @Test
    void zeroIsRefusedAndTooMuchIsCappedEachWithALogLine() {
        ArRobot robot = Cycles.p3dxRobot();
        double top = robot.getParameters().maxVelocity();
        try (CapturedLog log = new CapturedLog("robosim.aria")) {
            assertFalse(robot.setAbsoluteMaxTransVel(0));
            assertTrue(log.lines().stream().anyMatch(l -> l.contains("setAbsoluteMaxTransVel") && l.contains("will not set it")),
                    log.lines().toString());
            log.clear();
            assertTrue(robot.setAbsoluteMaxTransVel(top * 2));
            assertTrue(log.lines().stream().anyMatch(l -> l.contains("TransVelTop") && l.contains("will cap it")),
                    log.lines().toString());
        }
        assertEquals(top, robot.getAbsoluteMaxTransVel());
        assertFalse(robot.setAbsoluteMaxTransNegVel(10));
        assertFalse(robot.setAbsoluteMaxRotVel(-1));
        assertFalse(robot.setAbsoluteMaxTransAccel(0));
    }

    @Test
    void aLowerMaximumPullsTheVelocityLimitDownAndCapsLaterOnes() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        assertTrue(robot.setAbsoluteMaxTransVel(300));
        assertEquals(300, robot.getTransVelMax());
        assertEquals(new Command.SetMaxTransVel(300), robot.last());
        try (CapturedLog log = new CapturedLog("robosim.aria")) {
            robot.setTransVelMax(500);
            assertTrue(log.lines().stream().anyMatch(l -> l.contains("setTransVelMax of 500") && l.contains("capping it")),
                    log.lines().toString());
        }
        assertEquals(300, robot.getTransVelMax());
        assertTrue(robot.setAbsoluteMaxRotVel(40));
        assertEquals(40, robot.getRotVelMax());
        robot.setRotVelMax(90);
        assertEquals(40, robot.getRotVelMax());
    }

    @Test
    void aLowerAccelerationMaximumPullsTheAccelerationDownAndIsSent() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        double accel = robot.getTransAccel();
        assertTrue(robot.setAbsoluteMaxTransAccel(accel / 2));
        assertEquals(accel / 2, robot.getTransAccel());
        assertEquals(new Command.SetDriveLimit(Command.DriveLimit.TRANS_ACCEL, accel / 2), robot.last());
        robot.setTransAccel(accel);
        assertEquals(accel / 2, robot.getTransAccel(), "capped at the absolute maximum");
        assertTrue(robot.setAbsoluteMaxRotDecel(robot.getRotDecel() + 10));
        assertEquals(robot.getParameters().rotDecel(), robot.getRotDecel(), "a higher maximum leaves it");
    }

    @Test
    void theNegativeVelocityLimitIsArias() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        try (CapturedLog log = new CapturedLog("robosim.aria")) {
            robot.setTransNegVelMax(10);
            assertTrue(log.lines().stream().anyMatch(l -> l.contains("setTransNegVelMax of 10")), log.lines().toString());
        }
        assertEquals(-robot.getParameters().maxVelocity(), robot.getTransNegVelMax());
        robot.setTransNegVelMax(-100);
        assertEquals(-100, robot.getTransNegVelMax());
        robot.setVel(-500);
        assertEquals(new Command.SetVel(-100), robot.last());
        robot.setVel(400);
        assertEquals(new Command.SetVel(400), robot.last());
        robot.setTransNegVelMax(-100_000);
        assertEquals(-robot.getParameters().maxVelocity(), robot.getTransNegVelMax(), "capped at the absolute maximum");
        assertTrue(robot.setAbsoluteMaxTransNegVel(-50));
        assertEquals(-50, robot.getTransNegVelMax());
    }

    @Test
    void theLateralLimitsOfARobotWithoutLateralMotionStayZero() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        int sent = robot.sent.size();
        robot.setLatVelMax(500);
        robot.setLatAccel(300);
        robot.setLatDecel(300);
        robot.setLatVel(200);
        assertEquals(0, robot.getLatVelMax());
        assertEquals(0, robot.getLatAccel());
        assertEquals(0, robot.getLatDecel());
        assertEquals(0, robot.getLatVel());
        assertEquals(sent, robot.sent.size(), "nothing is sent for lateral motion");
        assertTrue(robot.setAbsoluteMaxLatVel(500));
        assertEquals(0, robot.getAbsoluteMaxLatVel(), "capped at the top, 0");
        assertFalse(robot.setAbsoluteMaxLatAccel(0));
    }
}
