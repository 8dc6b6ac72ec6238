package robosim.it;

import robosim.aria.ArRobot;
import robosim.aria.ArUtil;

/**
 * A robot program for the end-to-end tests that fails mid-run, as a student's might: it connects,
 * drives for half a second of simulated time, then throws from a method of its own. Arguments:
 * NAME HOST PORT.
 */
public final class FailingDriver {
    private FailingDriver() {
    }

    public static void main(String[] args) {
        ArRobot robot = new ArRobot(args[0], args[1], Integer.parseInt(args[2]), "p3dx");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("could not connect: " + robot.getConnectionError());
        }
        robot.enableMotors();
        robot.setVel(200);
        ArUtil.sleep(500);
        turnAtTheWall(robot);
    }

    private static void turnAtTheWall(ArRobot robot) {
        throw new IllegalStateException("no wall within " + Math.round(robot.getClosestSonarRange(-45, 45)) + " mm");
    }
}
