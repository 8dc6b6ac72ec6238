package robosim.aria;

import robosim.hw.RobotSensorResponse;
import robosim.protocol.RobotStates;
import robosim.params.ParameterFileReader;
import robosim.protocol.RobotParameters;

/** Robots whose cycles a test drives by hand, with no Environment. */
final class Cycles {
    private static final int[] NONE = new int[0];

    private Cycles() {
    }

    static RobotParameters p3dx() {
        return ParameterFileReader.read(ClosestSonarTest.p3dxFile());
    }

    /** The p3dx with its laser mounted elsewhere. */
    static RobotParameters p3dxWithLaser(double x, double y, double th, double maxRange) {
        RobotParameters p = p3dx();
        return new RobotParameters(p.robotClass(), p.subclass(), p.robotRadius(), p.robotWidth(),
                p.robotLengthFront(), p.robotLengthRear(), p.maxVelocity(), p.maxRVelocity(), p.transAccel(),
                p.transDecel(), p.rotAccel(), p.rotDecel(), p.diffConvFactor(), p.sonarMaxRange(), p.sonarUnits(),
                x, y, th, maxRange);
    }

    static ArRobot robot(RobotParameters parameters) {
        return new ArRobot("r", "127.0.0.1", 5000, parameters);
    }

    static ArRobot p3dxRobot() {
        return robot(p3dx());
    }

    /** One cycle at a pose, with no sonar or laser readings. */
    static void cycle(ArRobot robot, long timeMs, double x, double y, double th) {
        cycle(robot, timeMs, x, y, th, NONE, NONE);
    }

    /** One cycle at a pose, with sonar ranges (16, or none) and a laser scan (or none). */
    static void cycle(ArRobot robot, long timeMs, double x, double y, double th, int[] sonar, int[] laser) {
        robot.responded(new RobotSensorResponse(RobotStates.of(robot.getCounter() + 1, timeMs, x, y, th,
                0, 0, 0, 0, false, sonar, 0, laser, null)));
    }

    /** One cycle at the origin, driving at these velocities. */
    static void cycleMoving(ArRobot robot, long timeMs, double vel, double rotVel) {
        robot.responded(new RobotSensorResponse(RobotStates.of(robot.getCounter() + 1, timeMs, 0, 0, 0,
                vel, rotVel, vel, vel, false, NONE, 0, NONE, null)));
    }
}
