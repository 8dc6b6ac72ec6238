package robosim.aria;

import robosim.hw.RobotSensorResponse;
import robosim.protocol.RobotStates;

/**
 * A p3dx whose cycles a test drives by hand, to fire one action on literal poses and velocities:
 * the action is given the robot (as addAction does) but fired by the test, not by the cycle.
 */
final class ActionFixture {
    final ArRobot robot = Cycles.p3dxRobot();
    private long time;

    <A extends ArAction> A attach(A action) {
        action.setRobot(robot);
        return action;
    }

    /** One cycle with the robot at a pose, driving at a velocity. */
    ActionFixture at(double x, double y, double th, double vel) {
        time += 100;
        robot.responded(new RobotSensorResponse(RobotStates.of(robot.getCounter() + 1, time, x, y, th,
                vel, 0, vel, vel, false, new int[0], 0, new int[0], null)));
        return this;
    }

    /** Fires the action with nothing desired by higher priorities. */
    static ArActionDesired fire(ArAction action) {
        return action.fire(new ArActionDesired());
    }
}
