package robosim.examples.wander;

import robosim.aria.ArRobot;
import robosim.aria.ArUtil;

/**
 * A Pioneer that wanders and keeps off the walls using its sonars only: it drives ahead while the
 * front is clear, steers away from a near side wall, turns in place towards the more open side when
 * something is ahead, and backs off when it stalls.
 *
 * <p>Run it as {@code bin/robosim robot robosim.examples.wander.Wander NAME HOST PORT [PARAMFILE]}.
 */
public final class Wander {
    private static final int CRUISE = 350;
    private static final int FRONT_STOP = 700;
    private static final int SIDE_NEAR = 450;

    private final ArRobot robot;
    private int turnDirection;
    private int backingOff;

    /** @param robot a connected robot */
    public Wander(ArRobot robot) {
        this.robot = robot;
    }

    /**
     * Runs a wander robot until the Environment ends the run.
     *
     * @param args NAME HOST PORT [PARAMFILE], as the original's robot applications
     */
    public static void main(String[] args) {
        if (args.length < 3) {
            throw new IllegalArgumentException("usage: Wander NAME HOST PORT [PARAMFILE]");
        }
        ArRobot robot = new ArRobot(args[0], args[1], Integer.parseInt(args[2]), args.length > 3 ? args[3] : "p3dx");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("robot " + args[0] + " could not connect: " + robot.getConnectionError());
        }
        robot.enableMotors(); // a Pioneer's motors are disabled when its program connects, as in ARIA
        new Wander(robot).run();
        robot.disconnect();
    }

    /** Wanders, one decision per step, until the robot is disconnected. */
    public void run() {
        while (robot.isConnected()) {
            decide();
            ArUtil.sleep(robot.getStepMs());
        }
    }

    /** One step's decision from the current sonar readings. */
    void decide() {
        if (robot.isStalled() && backingOff == 0) {
            backingOff = 8;
            robot.setRotVel(0);
            robot.setVel(-150);
            return;
        }
        if (backingOff > 0) {
            backingOff--;
            if (backingOff == 0) {
                robot.setVel(0);
            }
            return;
        }
        int front = robot.getClosestSonarRange(-40, 40);
        int left = robot.getClosestSonarRange(40, 100);
        int right = robot.getClosestSonarRange(-100, -40);
        if (front < FRONT_STOP) {
            if (turnDirection == 0) {
                turnDirection = left >= right ? 1 : -1;
            }
            robot.setVel(0);
            robot.setRotVel(35 * turnDirection);
            return;
        }
        turnDirection = 0;
        robot.setVel(front < 2 * FRONT_STOP ? CRUISE / 2 : CRUISE);
        if (left < SIDE_NEAR && left < right) {
            robot.setRotVel(-12);
        } else if (right < SIDE_NEAR) {
            robot.setRotVel(12);
        } else {
            robot.setRotVel(0);
        }
    }
}
