package robosim.it;

import robosim.aria.ArRobot;
import robosim.aria.ArUtil;

/**
 * A robot program for the end-to-end tests: drives, turns, and prints what its sonars read.
 * Arguments: NAME HOST PORT.
 */
public final class SonarDriver {
    private SonarDriver() {
    }

    public static void main(String[] args) {
        ArRobot robot = new ArRobot(args[0], args[1], Integer.parseInt(args[2]), "p3dx");
        if (!robot.blockingConnect()) {
            System.out.println("FAILED " + robot.getConnectionError());
            System.exit(3);
        }
        robot.enableMotors();
        System.out.println("sonar before " + robot.getSonarRange(3));
        ArUtil.sleep(100);
        System.out.println("sonar first " + robot.getSonarRange(3) + " step " + robot.getStep());
        robot.move(600);
        while (!robot.isMoveDone() && robot.isConnected()) {
            ArUtil.sleep(100);
        }
        robot.setDeltaHeading(90);
        while (!robot.isHeadingDone() && robot.isConnected()) {
            ArUtil.sleep(100);
        }
        System.out.printf("pose %.1f %.1f %.1f%n", robot.getX(), robot.getY(), robot.getTh());
        System.out.println("sonar after " + robot.getSonarRange(3) + " closest front " + robot.getClosestSonarRange(-45, 45));
        robot.disconnect();
    }
}
