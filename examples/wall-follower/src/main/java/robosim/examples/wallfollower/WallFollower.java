package robosim.examples.wallfollower;

import robosim.aria.ArRobot;
import robosim.aria.ArSick;
import robosim.aria.ArUtil;

/**
 * A Pioneer that follows the wall on its right at about {@link #DISTANCE} mm, by its SICK laser:
 * it drives straight until it meets a wall, turns left in place until the wall is on its right,
 * then steers to keep the distance, turning left again at each corner.
 *
 * <p>Run it as {@code bin/robosim robot robosim.examples.wallfollower.WallFollower NAME HOST PORT}.
 */
public final class WallFollower {
    /** The distance kept from the wall, mm from the robot's centre. */
    public static final int DISTANCE = 600;
    private static final int CRUISE = 300;
    private static final int FRONT_TURN = 900;
    private static final int WALL_SEEN = 2 * DISTANCE;

    private final ArRobot robot;
    private final ArSick laser = new ArSick();

    /**
     * Attaches a laser to a robot that is not connected yet.
     *
     * @param robot the robot; connect it with {@link #connect()}
     */
    public WallFollower(ArRobot robot) {
        this.robot = robot;
        robot.addRangeDevice(laser);
    }

    /**
     * Runs a wall follower until the Environment ends the run.
     *
     * @param args NAME HOST PORT
     */
    public static void main(String[] args) {
        if (args.length != 3) {
            throw new IllegalArgumentException("usage: WallFollower NAME HOST PORT");
        }
        WallFollower follower = new WallFollower(new ArRobot(args[0], args[1], Integer.parseInt(args[2]), "p3dx"));
        follower.connect();
        follower.run();
    }

    /**
     * Connects the robot, enables its motors (a Pioneer's are disabled when its program connects, as
     * in ARIA) and switches its laser on.
     *
     * @throws IllegalStateException if either fails, with the reason
     */
    public void connect() {
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("robot " + robot.getName() + " could not connect: "
                    + robot.getConnectionError());
        }
        robot.enableMotors();
        if (!laser.blockingConnect()) {
            throw new IllegalStateException("the laser of robot " + robot.getName() + " could not connect: "
                    + laser.getConnectionError());
        }
    }

    /** Follows the wall, one decision per step, until the robot is disconnected. */
    public void run() {
        while (robot.isConnected()) {
            decide(laser.getRawScan());
            ArUtil.sleep(robot.getStepMs());
        }
    }

    /** One step's decision from the latest scan (empty before the first one arrives). */
    private void decide(int[] scan) {
        if (scan.length < 2) {
            return;
        }
        int front = closest(scan, -25, 25);
        int right = closest(scan, -100, -50);
        if (front < FRONT_TURN) {
            robot.setVel(0);
            robot.setRotVel(30);
        } else if (right > WALL_SEEN) {
            robot.setVel(CRUISE);
            robot.setRotVel(0);
        } else {
            // steer in proportion to the error: too far turns right (negative), too near turns left
            double turn = -0.08 * (right - DISTANCE);
            robot.setVel(CRUISE);
            robot.setRotVel(Math.max(-20, Math.min(20, turn)));
        }
    }

    /**
     * @return the shortest range of the scan between two angles, degrees from straight ahead,
     *         positive to the left; a scan runs from 90° right to 90° left
     */
    static int closest(int[] scan, double from, double to) {
        double step = 180.0 / (scan.length - 1);
        int min = Integer.MAX_VALUE;
        for (int i = 0; i < scan.length; i++) {
            double angle = -90 + i * step;
            if (angle >= from && angle <= to) {
                min = Math.min(min, scan[i]);
            }
        }
        return min;
    }
}
