package robosim.examples.square;

import java.io.PrintStream;
import robosim.aria.ArPose;
import robosim.aria.ArRobot;
import robosim.aria.ArUtil;

/**
 * The README's first robot program: a Pioneer drives a square of 1 m sides, turning left at each
 * corner, prints its pose and front sonar at every corner, and leaves the run. {@code move} and
 * {@code setDeltaHeading} do not block; the program waits for each in simulated time.
 *
 * <p>Run it as {@code bin/robosim robot robosim.examples.square.Square NAME HOST PORT}.
 */
public final class Square {
    /** The side of the square, mm. */
    public static final double SIDE = 1000;

    private Square() {
    }

    /**
     * Connects a Pioneer 3-DX, drives the square and disconnects.
     *
     * @param args NAME HOST PORT
     */
    public static void main(String[] args) {
        if (args.length != 3) {
            throw new IllegalArgumentException("usage: Square NAME HOST PORT");
        }
        ArRobot robot = new ArRobot(args[0], args[1], Integer.parseInt(args[2]), "p3dx");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("robot " + args[0] + " could not connect: " + robot.getConnectionError());
        }
        robot.enableMotors(); // a Pioneer's motors are disabled when its program connects, as in ARIA
        drive(robot, System.out);
        robot.disconnect();
    }

    /**
     * Drives the square with a connected robot, printing a line per corner.
     *
     * @param robot a connected robot
     * @param out   where the corners are printed
     * @return the pose at each of the four corners, the last one where it started
     */
    public static ArPose[] drive(ArRobot robot, PrintStream out) {
        ArPose[] corners = new ArPose[4];
        for (int side = 0; side < 4 && robot.isConnected(); side++) {
            robot.move(SIDE);
            while (!robot.isMoveDone() && robot.isConnected()) {
                ArUtil.sleep(100);
            }
            robot.setDeltaHeading(90);
            while (!robot.isHeadingDone() && robot.isConnected()) {
                ArUtil.sleep(100);
            }
            corners[side] = robot.getPose();
            out.println("pose " + corners[side] + ", front sonar " + robot.getClosestSonarRange(-45, 45) + " mm");
        }
        return corners;
    }
}
