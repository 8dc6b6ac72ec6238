package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.aria.ArActionTriangleDriveTo.State;

/**
 * ArLineFinder.cpp and ArActionTriangleDriveTo.cpp on the simulated laser: a scan of a docking
 * target (two 254 mm sides at 135 degrees) gives two lines and their vertex, and the action drives
 * through ARIA's states to the final point.
 */
class ArActionTriangleDriveToTest {
    private final ArRobot robot = Cycles.p3dxRobot();
    private final ArSick sick = new ArSick();
    private long time;

    ArActionTriangleDriveToTest() {
        robot.addRangeDevice(sick);
    }

    /**
     * Segments as {x1, y1, x2, y2}: a docking target, a wedge whose point is at (vx, 0) pointing at
     * the robot (toward -x), its sides going away at half the inside angle either side of +x.
     */
    private static double[][] target(double vx, double side, double inside) {
        double half = inside / 2;
        double a1 = Math.toRadians(half);
        double a2 = Math.toRadians(-half);
        return new double[][] {
            {vx, 0, vx + side * Math.cos(a1), side * Math.sin(a1)},
            {vx, 0, vx + side * Math.cos(a2), side * Math.sin(a2)},
        };
    }

    /** A 181-beam scan from the p3dx's laser (18 mm ahead) at (x, 0) facing +x, of the segments. */
    private static int[] scan(double x, double[][] segments) {
        return scan(x, 0, 0, segments);
    }

    /** A 181-beam scan from the p3dx's laser (18 mm ahead) with the robot at (x, y, th), of the segments. */
    private static int[] scan(double x, double y, double th, double[][] segments) {
        int[] s = new int[181];
        double ox = x + 18 * Math.cos(Math.toRadians(th));
        double oy = y + 18 * Math.sin(Math.toRadians(th));
        for (int i = 0; i < 181; i++) {
            double a = Math.toRadians(th - 90 + i);
            double dx = Math.cos(a);
            double dy = Math.sin(a);
            double best = 8000;
            for (double[] g : segments) {
                double ex = g[2] - g[0];
                double ey = g[3] - g[1];
                double den = dx * ey - dy * ex;
                if (Math.abs(den) < 1e-12) {
                    continue;
                }
                double t = ((g[0] - ox) * ey - (g[1] - oy) * ex) / den;
                double u = ((g[0] - ox) * dy - (g[1] - oy) * dx) / den;
                if (t > 0 && u >= 0 && u <= 1) {
                    best = Math.min(best, t);
                }
            }
            s[i] = (int) Math.round(best);
        }
        return s;
    }

    private void at(double x, double vel, double[][] world) {
        time += 100;
        Cycles.cycle(robot, time, x, 0, 0, new int[0], scan(x, world));
        if (vel != 0) {
            time += 100;
            robot.responded(new robosim.hw.RobotSensorResponse(robosim.protocol.RobotStates.of(robot.getCounter() + 1,
                    time, x, 0, 0, vel, 0, vel, vel, false, new int[0], 0, scan(x, world), null)));
        }
    }

    @Test
    void theLineFinderFindsTheTwoSidesOfTheTarget() {
        at(0, 0, target(1500, 254, 135));
        List<ArLineFinderSegment> lines = new ArLineFinder(sick).getLines();
        assertEquals(2, lines.size(), lines.toString());
        for (ArLineFinderSegment l : lines) {
            assertEquals(254, l.getLength(), 40, l.toString());
        }
        double between = ArMath.subAngle(180, ArMath.subAngle(lines.get(0).getLineAngle(), lines.get(1).getLineAngle()));
        assertEquals(135, between, 6, "in scan order, as ARIA's finder gives them");
    }

    @Test
    void aFlatWallIsOneLineAndNoTarget() {
        double[][] wall = {{1500, -1000, 1500, 1000}};
        at(0, 0, wall);
        List<ArLineFinderSegment> lines = new ArLineFinder(sick).getLines();
        assertEquals(1, lines.size(), lines.toString());
        ArActionTriangleDriveTo drive = new ArActionTriangleDriveTo();
        drive.setRobot(robot);
        drive.activate();
        ArActionDesired d = ActionFixture.fire(drive);
        assertEquals(State.STATE_ACQUIRE, drive.getState());
        assertFalse(drive.getVertexSeen());
        assertEquals(0, d.getVel());
    }

    @Test
    void itFindsTheVertexAndDrivesToTheApproachPointFirst() {
        at(0, 0, target(1500, 254, 135));
        ArActionTriangleDriveTo drive = new ArActionTriangleDriveTo();
        drive.setRobot(robot);
        assertNotNull(drive.getLineFinder(), "its own line finder on the robot's laser");
        assertNull(ActionFixture.fire(drive), "inactive until activated");
        drive.activate();
        ArActionDesired d = ActionFixture.fire(drive);
        assertTrue(drive.getVertexSeen());
        ArPose vertex = drive.getVertex();
        assertEquals(1500, vertex.getX(), 25, vertex.toString());
        assertEquals(0, vertex.getY(), 25, vertex.toString());
        assertEquals(180, Math.abs(vertex.getTh()), 5, vertex.toString());
        assertEquals(State.STATE_GOTO_APPROACH, drive.getState());
        assertEquals(200, d.getVel(), "500 mm to the approach point: the top speed");
        assertEquals(0, d.getHeading(), 5);
    }

    @Test
    void pastTheApproachPointItGoesToTheFinalPointThenAlignsAndSucceeds() {
        double[][] world = target(1500, 254, 135);
        at(1000, 0, world);
        ArActionTriangleDriveTo drive = new ArActionTriangleDriveTo();
        drive.setRobot(robot);
        drive.activate();
        ArActionDesired d = ActionFixture.fire(drive);
        assertEquals(State.STATE_GOTO_FINAL, drive.getState(), "the approach point is behind it");
        // the final point is 400 mm from the vertex: about 100 mm ahead
        assertEquals(Math.sqrt(100 * 100 * 2), d.getVel(), 25);
        at(1095, 0, world);
        d = ActionFixture.fire(drive);
        assertEquals(State.STATE_SUCCEEDED, drive.getState(), "within the close distance, stopped, facing it");
        assertEquals(0, d.getVel());
        assertEquals(0, d.getRotVel());
    }

    @Test
    void withGotoVertexItDrivesStraightInToTheFinalDistance() {
        double[][] world = target(1500, 254, 135);
        at(0, 0, world);
        ArActionTriangleDriveTo drive = new ArActionTriangleDriveTo("tri", 400, 0);
        drive.setGotoVertex(true);
        drive.setRobot(robot);
        drive.activate();
        ArActionDesired d = ActionFixture.fire(drive);
        assertEquals(State.STATE_GOTO_VERTEX, drive.getState());
        assertEquals(200, d.getVel());
        assertEquals(0, d.getDeltaHeading(), 2);
    }

    @Test
    void unseenForLongerThanItsTimeItFailsOrSearches() {
        double[][] nothing = {};
        at(0, 0, nothing);
        ArActionTriangleDriveTo drive = new ArActionTriangleDriveTo();
        drive.setRobot(robot);
        drive.setVertexUnseenStopMSecs(1000);
        drive.activate();
        ActionFixture.fire(drive);
        assertEquals(State.STATE_ACQUIRE, drive.getState());
        for (int i = 0; i < 11; i++) {
            at(0, 0, nothing);
        }
        ArActionDesired d = ActionFixture.fire(drive);
        assertEquals(State.STATE_FAILED, drive.getState());
        assertEquals(0, d.getVel());
        drive.setAcquire(true);
        drive.activate();
        ActionFixture.fire(drive);
        for (int i = 0; i < 11; i++) {
            at(0, 0, nothing);
        }
        d = ActionFixture.fire(drive);
        assertEquals(State.STATE_SEARCHING, drive.getState());
        assertEquals(30, d.getRotVel());
        drive.deactivate();
        assertEquals(State.STATE_INACTIVE, drive.getState());
    }

    @Test
    void drivenByWhatItAsksForItEndsInFrontOfTheTargetFacingIt() {
        double[][] world = target(2500, 254, 135);
        double x = 0;
        double y = 400;
        double th = 10;
        double vel = 0;
        ArActionTriangleDriveTo drive = new ArActionTriangleDriveTo();
        drive.setRobot(robot);
        ArPriorityResolver resolver = new ArPriorityResolver();
        List<ArResolver.Entry> actions = List.of(new ArResolver.Entry(50, drive));
        boolean activated = false;
        java.util.Set<State> states = new java.util.LinkedHashSet<>();
        for (int step = 0; step < 600 && drive.getState() != State.STATE_SUCCEEDED; step++) {
            time += 100;
            robot.responded(new robosim.hw.RobotSensorResponse(robosim.protocol.RobotStates.of(robot.getCounter() + 1,
                    time, x, y, th, vel, 0, vel, vel, false, new int[0], 0, scan(x, y, th, world), null)));
            if (!activated) {
                drive.activate();
                activated = true;
            }
            ArActionDesired d = resolver.resolve(actions, robot, false);
            states.add(drive.getState());
            // the robot: turns at most 10 degrees a step toward what is asked, then drives
            double turn = d.getDeltaHeadingStrength() > 0 ? d.getDeltaHeading()
                    : d.getRotVelStrength() > 0 ? d.getRotVel() * 0.1 : 0;
            th = ArMath.addAngle(th, Math.max(-10, Math.min(10, turn)));
            vel = d.getVelStrength() > 0 ? d.getVel() : 0;
            x += vel * 0.1 * Math.cos(Math.toRadians(th));
            y += vel * 0.1 * Math.sin(Math.toRadians(th));
        }
        assertEquals(State.STATE_SUCCEEDED, drive.getState(), "through " + states);
        assertTrue(states.contains(State.STATE_GOTO_APPROACH) && states.contains(State.STATE_GOTO_FINAL), states.toString());
        // the final point: 400 mm out from the vertex along its heading (toward -x)
        assertEquals(2100, x, 100, "x " + x);
        assertEquals(0, y, 100, "y " + y);
        assertEquals(0, th, 3, "facing the vertex");
    }

    @Test
    void withoutALaserActivatingFails() {
        ArRobot bare = Cycles.p3dxRobot();
        ArActionTriangleDriveTo drive = new ArActionTriangleDriveTo();
        drive.setRobot(bare);
        drive.activate();
        assertEquals(State.STATE_FAILED, drive.getState());
    }
}
