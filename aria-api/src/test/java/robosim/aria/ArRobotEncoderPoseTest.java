package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import robosim.protocol.Command;

/**
 * The encoder, raw and global poses keep ARIA's relations (ArRobot.h, ArRobot.cpp: setEncoderPose,
 * setRawEncoderPose, setDeadReconPose, setEncoderTransform, getToGlobalTransform), and the robot's
 * motion goes on from a pose set; headings are sent in the Environment's frame.
 */
class ArRobotEncoderPoseTest {
    private static final double EPS = 1e-9;

    private static void assertPose(double x, double y, double th, ArPose p) {
        assertEquals(x, p.getX(), 1e-6, "x of " + p);
        assertEquals(y, p.getY(), 1e-6, "y of " + p);
        assertEquals(th, p.getTh(), 1e-6, "th of " + p);
    }

    @Test
    void anEncoderPoseSetIsWhereTheMotionGoesOnFrom() {
        ArRobot robot = Cycles.p3dxRobot();
        Cycles.cycle(robot, 100, 100, 0, 0);
        robot.setEncoderPose(new ArPose(1000, 1000, 90));
        assertPose(1000, 1000, 90, robot.getEncoderPose());
        assertPose(1000, 1000, 90, robot.getPose());
        assertPose(100, 0, 0, robot.getRawEncoderPose());
        Cycles.cycle(robot, 200, 200, 0, 0); // 100 mm straight ahead
        assertPose(1000, 1100, 90, robot.getEncoderPose());
        assertEquals(1000, robot.getEncoderX(), 1e-6);
        assertEquals(1100, robot.getEncoderY(), 1e-6);
        assertEquals(90, robot.getEncoderTh(), 1e-6);
        assertPose(200, 0, 0, robot.getRawEncoderPose());
    }

    @Test
    void aRawPoseSetLeavesTheEncoderPoseWhereItIs() {
        ArRobot robot = Cycles.p3dxRobot();
        Cycles.cycle(robot, 100, 100, 0, 0);
        robot.setRawEncoderPose(new ArPose(0, 0, 180));
        assertPose(0, 0, 180, robot.getRawEncoderPose());
        assertPose(100, 0, 0, robot.getEncoderPose());
        Cycles.cycle(robot, 200, 150, 0, 0);
        assertPose(-50, 0, 180, robot.getRawEncoderPose());
        assertPose(150, 0, 0, robot.getEncoderPose());
    }

    @Test
    void deadReconPoseChangesTheEncoderPoseButNotTheGlobalOneAndTellsTheCallbacks() {
        ArRobot robot = Cycles.p3dxRobot();
        AtomicInteger told = new AtomicInteger();
        robot.addSetEncoderTransformCB(told::incrementAndGet);
        Cycles.cycle(robot, 100, 100, 50, 0);
        robot.setDeadReconPose(new ArPose(0, 0, -90));
        assertEquals(1, told.get());
        assertPose(0, 0, -90, robot.getEncoderPose());
        assertPose(100, 50, 0, robot.getPose());
        Cycles.cycle(robot, 200, 300, 50, 0); // 200 mm ahead
        assertPose(0, -200, -90, robot.getEncoderPose());
        assertPose(300, 50, 0, robot.getPose());
    }

    @Test
    void setEncoderTransformMovesTheGlobalPoseAndTellsTheCallbacks() {
        ArRobot robot = Cycles.p3dxRobot();
        AtomicInteger told = new AtomicInteger();
        Runnable cb = told::incrementAndGet;
        robot.addSetEncoderTransformCB(cb);
        Cycles.cycle(robot, 100, 100, 0, 0);
        robot.setEncoderTransform(new ArPose(100, 0, 0), new ArPose(0, 0, 90));
        assertPose(0, 0, 90, robot.getPose());
        robot.setEncoderTransform(new ArPose(10, 20, 0));
        assertPose(110, 20, 0, robot.getPose());
        robot.moveTo(new ArPose(5, 5, 5));
        assertEquals(3, told.get(), "moveTo changes the encoder transform too");
        robot.remSetEncoderTransformCB(cb);
        robot.setEncoderTransform(new ArTransform());
        assertEquals(3, told.get());
        assertPose(100, 0, 0, robot.getPose());
    }

    @Test
    void theToGlobalAndToLocalTransformsAreAtTheRobotsPose() {
        ArRobot robot = Cycles.p3dxRobot();
        Cycles.cycle(robot, 100, 1000, 0, 90);
        assertPose(1000, 100, 90, robot.getToGlobalTransform().doTransform(new ArPose(100, 0, 0)));
        assertPose(100, 0, 0, robot.getToLocalTransform().doTransform(new ArPose(1000, 100, 90)));
        assertEquals(100, robot.findDistanceTo(new ArPose(1000, 100, 0)), EPS);
        assertEquals(90, robot.findAngleTo(new ArPose(1000, 100, 0)), EPS);
        assertEquals(-90, robot.findDeltaHeadingTo(new ArPose(1000, -100, 0)), EPS);
    }

    @Test
    void aHeadingIsSentInTheEnvironmentsFrame() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        robot.cycleWheels(0, 0, 0, 0, 0);
        robot.setEncoderPose(new ArPose(0, 0, 90));
        robot.moveTo(new ArPose(0, 0, 180));
        robot.setHeading(180);
        assertEquals(new Command.SetHeading(0), robot.last());
        robot.setHeading(-90);
        assertEquals(new Command.SetHeading(90), robot.last());
    }

    @Test
    void thePoseHistoryInterpolatesPredictsAndRefusesAsArias() {
        ArRobot robot = Cycles.p3dxRobot();
        ArPose p = new ArPose();
        assertEquals(-3, robot.getPoseInterpPosition(at(100), p));
        Cycles.cycle(robot, 100, 0, 0, 0);
        Cycles.cycle(robot, 200, 100, 0, 10);
        assertEquals(1, robot.getPoseInterpPosition(at(150), p));
        assertPose(50, 0, 5, p);
        assertEquals(0, robot.getPoseInterpPosition(at(250), p));
        assertPose(150, 0, 15, p);
        assertEquals(-2, robot.getPoseInterpPosition(at(50), p));
        assertEquals(-1, robot.getPoseInterpPosition(at(200 + 51 * 100), p));
        robot.setPoseInterpNumReadings(1);
        assertEquals(1, robot.getPoseInterpNumReadings());
        assertEquals(-2, robot.getPoseInterpPosition(at(150), p));
        assertEquals(100, robot.getEncoderPoseInterpNumReadings());
    }

    @Test
    void applyEncoderOffsetCarriesAPoseByTheMotionBetweenTwoTimes() {
        ArRobot robot = Cycles.p3dxRobot();
        Cycles.cycle(robot, 100, 0, 0, 0);
        Cycles.cycle(robot, 200, 100, 0, 0);
        Cycles.cycle(robot, 300, 200, 0, 0);
        ArPose result = new ArPose();
        assertEquals(1, robot.applyEncoderOffset(new ArPose(5000, 5000, 0), at(100), at(300), result));
        assertPose(5200, 5000, 0, result);
        assertEquals(-2, robot.applyEncoderOffset(new ArPose(), at(0), at(300), result));
    }

    @Test
    void theOdometryDelayStampsTheHistoryEarlier() {
        ArRobot robot = Cycles.p3dxRobot();
        robot.setOdometryDelay(50);
        Cycles.cycle(robot, 100, 0, 0, 0);
        Cycles.cycle(robot, 200, 100, 0, 0);
        ArPose p = new ArPose();
        assertEquals(1, robot.getPoseInterpPosition(at(150), p));
        assertPose(100, 0, 0, p);
        assertEquals(50, robot.getOdometryDelay());
    }

    private static ArTime at(long ms) {
        ArTime t = new ArTime();
        t.setSec(ms / 1000);
        t.setMSec(ms % 1000);
        return t;
    }
}
