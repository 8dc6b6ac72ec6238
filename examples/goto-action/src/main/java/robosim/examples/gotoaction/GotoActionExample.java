package robosim.examples.gotoaction;

import java.io.PrintStream;
import java.util.Locale;
import robosim.aria.ArActionGotoStraight;
import robosim.aria.ArActionLimiterForwards;
import robosim.aria.ArActionStop;
import robosim.aria.ArPose;
import robosim.aria.ArRobot;
import robosim.aria.ArSonarDevice;

/**
 * ARIA's examples/gotoActionExample.cpp: the robot drives a square, 2.5 m a side by default, by
 * giving an {@link ArActionGotoStraight} each corner in turn as its goal, with a collision-avoiding
 * limiter above it and a stopping action below it (so the robot stops when it has no goal). After
 * its time it cancels the goal, waits 3 s while the stopping action stops it, and leaves.
 *
 * <p>The corners are taken in the frame of the robot's start pose, as ARIA's are in odometry that
 * starts at (0, 0, 0). Its actions are ARIA's: two {@link ArActionLimiterForwards} (near and far)
 * above the goto and an {@link ArActionStop} below it; ARIA's table-sensor limiter is left out, as
 * RoboSim's robots have no table-sensing IR.
 * Time is the simulation's: the duration is in simulated seconds.
 *
 * <p>Run it as {@code bin/robosim robot robosim.examples.gotoaction.GotoActionExample NAME HOST PORT
 * [SIDE_MM [SECONDS]]}.
 */
public final class GotoActionExample {
    /** ARIA's side of the square, mm. */
    public static final double DEFAULT_SIDE = 2500;
    /** ARIA's duration, s. */
    public static final int DEFAULT_SECONDS = 30;

    private GotoActionExample() {
    }

    /**
     * Connects a Pioneer 3-DX, drives the square for the duration and disconnects.
     *
     * @param args NAME HOST PORT [SIDE_MM [SECONDS]]
     */
    public static void main(String[] args) {
        if (args.length < 3 || args.length > 5) {
            throw new IllegalArgumentException("usage: GotoActionExample NAME HOST PORT [SIDE_MM [SECONDS]]");
        }
        double side = args.length > 3 ? positive("SIDE_MM", args[3]) : DEFAULT_SIDE;
        int seconds = args.length > 4 ? (int) positive("SECONDS", args[4]) : DEFAULT_SECONDS;
        ArRobot robot = new ArRobot(args[0], args[1], Integer.parseInt(args[2]), "p3dx");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("robot " + args[0] + " could not connect: " + robot.getConnectionError());
        }
        robot.enableMotors();
        drive(robot, side, seconds * 1000L, System.out);
        robot.disconnect();
    }

    private static double positive(String name, String value) {
        try {
            double v = Double.parseDouble(value);
            if (v > 0) {
                return v;
            }
        } catch (NumberFormatException e) {
            // answered below
        }
        throw new IllegalArgumentException("'" + value + "' was supplied for " + name + ": it must be a number above 0");
    }

    /**
     * Drives the square with a connected robot for a time, printing each new goal.
     *
     * @param robot      a connected robot
     * @param side       the square's side, mm
     * @param durationMs how long to drive, simulated ms
     * @param out        where the goals are printed
     * @return how many goals were achieved
     */
    public static int drive(ArRobot robot, double side, long durationMs, PrintStream out) {
        robot.addRangeDevice(new ArSonarDevice());
        robot.addAction(new ArActionLimiterForwards("speed limiter near", 300, 600, 250, 1), 95);
        robot.addAction(new ArActionLimiterForwards("speed limiter far", 300, 1100, 400, 1), 90);
        ArActionGotoStraight gotoPose = new ArActionGotoStraight("gotostraight", 400);
        robot.addAction(gotoPose, 50);
        robot.addAction(new ArActionStop("stop"), 40);

        ArPose start = robot.getPose();
        ArPose[] corners = {corner(start, side, 0), corner(start, side, side), corner(start, 0, side), corner(start, 0, 0)};
        out.printf(Locale.ROOT, "Going to four goals in turn for %d seconds, then cancelling goal and exiting.%n",
                durationMs / 1000);
        int achieved = 0;
        int goal = -1;
        long startMs = robot.getSimTimeMs();
        while (robot.isConnected()) {
            robot.lock();
            try {
                if (goal < 0 || gotoPose.haveAchievedGoal()) {
                    achieved += goal < 0 ? 0 : 1;
                    goal = (goal + 1) % corners.length;
                    gotoPose.setGoal(corners[goal]);
                    out.printf(Locale.ROOT, "Going to next goal at %.0f %.0f%n", gotoPose.getGoal().getX(),
                            gotoPose.getGoal().getY());
                }
                if (robot.getSimTimeMs() - startMs >= durationMs) {
                    out.printf(Locale.ROOT, "%d seconds have elapsed. Cancelling current goal, waiting 3 seconds,"
                            + " and exiting.%n", durationMs / 1000);
                    gotoPose.cancelGoal();
                    break;
                }
            } finally {
                robot.unlock();
            }
            robot.sleepSimulated(100);
        }
        robot.sleepSimulated(3000);
        return achieved;
    }

    /** A corner given in the start pose's frame, as a global pose. */
    private static ArPose corner(ArPose start, double ahead, double left) {
        double th = Math.toRadians(start.getTh());
        return new ArPose(start.getX() + ahead * Math.cos(th) - left * Math.sin(th),
                start.getY() + ahead * Math.sin(th) + left * Math.cos(th), 0);
    }
}
