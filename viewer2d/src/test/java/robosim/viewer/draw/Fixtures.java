package robosim.viewer.draw;

import java.util.List;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.HeatSource;
import robosim.protocol.WorldDescription.Obstacle;
import robosim.protocol.WorldDescription.RobotInfo;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/**
 * A literal world shared by the tests: 4000 x 2000 mm, one 500 mm square obstacle from (1000, 500)
 * to (1500, 1000), and one robot "r1", 400 mm long (200 ahead, 200 behind) and 380 mm wide, with
 * sonar 0 at its nose looking forward and sonar 1 on its left side looking left. Drawn 800 px wide,
 * 1 px is 5 mm and the image is 800 x 400.
 */
public final class Fixtures {
    public static final int WIDTH_PX = 800;

    private Fixtures() {
    }

    public static RobotParameters params() {
        return new RobotParameters("Pioneer", "test", 250, 380, 200, 200, 1000, 300, 300, 300, 100, 100,
                0.006, 5000, List.of(new SonarUnit(0, 200, 0, 0), new SonarUnit(1, 0, 190, 90)));
    }

    /** As {@link #params()}, with the laser mounted at (x, y) mm heading th degrees in the robot snapshot. */
    public static RobotParameters params(double laserX, double laserY, double laserTh, double laserMaxRange) {
        RobotParameters p = params();
        return new RobotParameters(p.robotClass(), p.subclass(), p.robotRadius(), p.robotWidth(),
                p.robotLengthFront(), p.robotLengthRear(), p.maxVelocity(), p.maxRVelocity(), p.transAccel(),
                p.transDecel(), p.rotAccel(), p.rotDecel(), p.diffConvFactor(), p.sonarMaxRange(), p.sonarUnits(),
                laserX, laserY, laserTh, laserMaxRange);
    }

    public static WorldDescription world() {
        return world(params(), List.of());
    }

    /** The fixture world with r1 given these parameters, and these heat sources. */
    public static WorldDescription world(RobotParameters r1, List<HeatSource> heat) {
        Obstacle square = new Obstacle(new double[] {1000, 500, 1500, 500, 1500, 1000, 1000, 1000}, 500);
        return new WorldDescription("fixture", 4000, 2000, 100, List.of(square),
                List.of(new RobotInfo("r1", "Pioneer", r1)), heat);
    }

    public static RobotView robot(double x, double y, double th, boolean stalled, boolean connected) {
        return new RobotView("r1", x, y, th, stalled, connected, new int[] {500, 300});
    }

    /** r1 at a true pose, believing itself at an odometry pose, with a laser scan. */
    public static RobotView robot(double x, double y, double th, double odoX, double odoY, double odoTh,
                           int[] laser, double laserIncrement) {
        return new RobotView("r1", x, y, th, false, true, new int[] {500, 300}, odoX, odoY, odoTh, laser,
                laserIncrement);
    }

    /** The robot at (3000, 600) heading along +x, moving freely; its centre is pixel (600, 280). */
    public static RobotView robotAtRest() {
        return robot(3000, 600, 0, false, true);
    }

    public static Snapshot snapshot(long step, RobotView... robots) {
        return new Snapshot(step, step * 100, List.of(robots));
    }
}
