package robosim.aria;

import robosim.hw.RobotSensorResponse;
import robosim.protocol.RobotState;
import robosim.protocol.params.ParameterFileReader;
import robosim.protocol.params.RobotParameters;

/**
 * A p3dx {@link ArRobot} whose cycles a test drives by hand, with no Environment: each cycle's state
 * becomes the robot's latest state before the cycle runs, as the hardware simulator makes it.
 */
final class CycleRobot extends ArRobot {
    private static final int[] NONE = new int[0];

    private volatile RobotState last;
    private long step;

    CycleRobot(RobotParameters parameters) {
        super("r", "127.0.0.1", 5000, parameters);
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

    @Override
    protected void responded(RobotSensorResponse response) {
        last = response.state();
        super.responded(response);
    }

    @Override
    protected RobotState state() {
        return last;
    }

    /** One cycle at a pose, with no sonar or laser readings. */
    void cycle(long timeMs, double x, double y, double th) {
        cycle(timeMs, x, y, th, NONE, NONE);
    }

    /** One cycle at a pose, with sonar ranges (16, or none) and a laser scan (or none). */
    void cycle(long timeMs, double x, double y, double th, int[] sonar, int[] laser) {
        step++;
        responded(new RobotSensorResponse(
                new RobotState(step, timeMs, x, y, th, 0, 0, 0, 0, false, sonar, 0, laser, null)));
    }
}
