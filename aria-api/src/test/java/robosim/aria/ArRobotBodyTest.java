package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * What ArRobot answers about its body from its parameter file (the p3dx: 511 mm long, 210 ahead of
 * its centre and 301 behind; front and rear rings of five bumpers), about its battery, and about
 * the frame its pose is given in.
 */
class ArRobotBodyTest {
    @Test
    void theLengthsAheadAndBehindTheCentreComeFromTheFileAndMakeTheWholeLength() {
        ArRobot robot = new ArRobot("r", "127.0.0.1", 5000, "p3dx");
        assertEquals(210, robot.getRobotLengthFront());
        assertEquals(301, robot.getRobotLengthRear());
        assertEquals(robot.getRobotLength(), robot.getRobotLengthFront() + robot.getRobotLengthRear());
    }

    @Test
    void theRearRingIsWhatTheFileDeclaresAndAriasDefaultIsNone() {
        ArRobot p3dx = new ArRobot("r", "127.0.0.1", 5000, "p3dx");
        assertTrue(p3dx.hasRearBumpers());
        assertEquals(5, p3dx.getNumRearBumpers());
        ArRobot bare = Cycles.robot(Cycles.p3dx()); // parameters without a file: ARIA's defaults
        assertFalse(bare.hasRearBumpers());
        assertEquals(5, bare.getNumRearBumpers(), "ARIA's default count, though there is no ring");
        assertFalse(bare.isRearBumperTriggered());
    }

    @Test
    void theEncoderTransformIsTheIdentityUntilMoveToAndThenCarriesTheEncoderPoseOntoThePose() {
        ArRobot robot = Cycles.p3dxRobot();
        Cycles.cycle(robot, 100, 1000, 500, 30);
        ArPose encoder = robot.getEncoderPose();
        ArPose same = robot.getEncoderTransform().doTransform(encoder);
        assertEquals(1000, same.getX(), 1e-9);
        assertEquals(500, same.getY(), 1e-9);
        assertEquals(30, same.getTh(), 1e-9);

        robot.moveTo(new ArPose(0, 0, 90));
        ArTransform t = robot.getEncoderTransform();
        assertEquals(60, t.getTh(), 1e-9);
        ArPose pose = t.doTransform(robot.getEncoderPose());
        assertEquals(0, pose.getX(), 1e-9);
        assertEquals(0, pose.getY(), 1e-9);
        assertEquals(90, pose.getTh(), 1e-9);

        Cycles.cycle(robot, 200, 1100, 500, 30); // the encoders say 100 mm along +x
        ArPose moved = robot.getEncoderTransform().doTransform(robot.getEncoderPose());
        assertEquals(robot.getPose().getX(), moved.getX(), 1e-9);
        assertEquals(robot.getPose().getY(), moved.getY(), 1e-9);
        assertEquals(100 * Math.cos(Math.toRadians(60)), moved.getX(), 1e-9, "turned by the transform's 60 degrees");
        assertEquals(100 * Math.sin(Math.toRadians(60)), moved.getY(), 1e-9);
    }
}
