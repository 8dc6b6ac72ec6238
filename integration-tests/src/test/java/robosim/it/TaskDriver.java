package robosim.it;

import robosim.aria.ArRobot;

/**
 * A robot program for the end-to-end tests whose work is a per-cycle task: it drives ahead and
 * returns from {@code main} at once, leaving the robot in the run ({@code runAsync}). Arguments:
 * NAME HOST PORT.
 */
public final class TaskDriver {
    private TaskDriver() {
    }

    public static void main(String[] args) {
        ArRobot robot = new ArRobot(args[0], args[1], Integer.parseInt(args[2]), "p3dx");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("could not connect: " + robot.getConnectionError());
        }
        robot.enableMotors();
        robot.addUserTask("ahead", 50, () -> robot.setVel(200));
        robot.runAsync();
    }
}
