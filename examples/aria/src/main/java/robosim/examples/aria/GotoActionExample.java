package robosim.examples.aria;

import robosim.aria.ArActionGotoStraight;
import robosim.aria.ArActionLimiterForwards;
import robosim.aria.ArActionLimiterTableSensor;
import robosim.aria.ArActionStop;
import robosim.aria.ArAnalogGyro;
import robosim.aria.ArArgumentParser;
import robosim.aria.ArCommands;
import robosim.aria.ArLaserConnector;
import robosim.aria.ArLog;
import robosim.aria.ArPose;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.ArSonarDevice;
import robosim.aria.ArTime;
import robosim.aria.ArUtil;
import robosim.aria.Aria;

/**
 * ARIA's {@code gotoActionExample.cpp}, line for line: an {@link ArActionGotoStraight} (under the
 * table-sensor limiter and two forward limiters, above an {@link ArActionStop} for when it has no
 * goal) drives the robot round a 2.5 m square, corner by corner from where it starts: (2500, 0),
 * (2500, 2500), (0, 2500), (0, 0), each set as the goal once the last is achieved. After 30 s it
 * cancels the goal, the stop action stops the robot, and 3 s later it exits.
 *
 * <p>The corners are in the robot's odometry, which starts at (0, 0, 0) on a Pioneer port, as on a
 * real Pioneer; a robot of the Environment reports its pose in the world, so its square has a
 * corner at the world's origin.
 */
public final class GotoActionExample {
    private GotoActionExample() {
    }

    /**
     * @param args RoboSim's {@code NAME HOST PORT}, or ARIA's robot and laser arguments ({@code -help})
     */
    public static void main(String[] args) {
        Aria.init();
        ArArgumentParser parser = new ArArgumentParser(args);
        parser.loadDefaultArguments();
        ArRobot robot = new ArRobot();
        ArAnalogGyro gyro = new ArAnalogGyro(robot);
        ArSonarDevice sonar = new ArSonarDevice();
        ArRobotConnector robotConnector = new ArRobotConnector(parser, robot);
        ArLaserConnector laserConnector = new ArLaserConnector(parser, robot, robotConnector);

        // Connect to the robot, get some initial data from it such as type and name,
        // and then load parameter files for this robot.
        if (!robotConnector.connectRobot()) {
            ArLog.log(ArLog.Terse, "gotoActionExample: Could not connect to the robot.");
            if (parser.checkHelpAndWarnUnparsed()) {
                // -help not given
                Aria.logOptions();
                Aria.exit(1);
                return;
            }
        }

        if (!Aria.parseArgs() || !parser.checkHelpAndWarnUnparsed()) {
            Aria.logOptions();
            Aria.exit(1);
            return;
        }

        ArLog.log(ArLog.Normal, "gotoActionExample: Connected to robot.");

        robot.addRangeDevice(sonar);
        robot.runAsync(true);

        // Collision avoidance actions at higher priority
        ArActionLimiterForwards limiterAction = new ArActionLimiterForwards("speed limiter near", 300, 600, 250);
        ArActionLimiterForwards limiterFarAction = new ArActionLimiterForwards("speed limiter far", 300, 1100, 400);
        ArActionLimiterTableSensor tableLimiterAction = new ArActionLimiterTableSensor();
        robot.addAction(tableLimiterAction, 100);
        robot.addAction(limiterAction, 95);
        robot.addAction(limiterFarAction, 90);

        // Goto action at lower priority
        //ArActionGoto gotoPoseAction("goto");
        ArActionGotoStraight gotoPoseAction = new ArActionGotoStraight("gotostraight");
        robot.addAction(gotoPoseAction, 50);

        // Stop action at lower priority, so the robot stops if it has no goal
        ArActionStop stopAction = new ArActionStop("stop");
        robot.addAction(stopAction, 40);

        // turn on the motors, turn off amigobot sounds
        robot.enableMotors();
        robot.comInt(ArCommands.SOUNDTOG, 0);

        final int duration = 30000; //msec
        ArLog.log(ArLog.Normal, "Going to four goals in turn for %d seconds, then cancelling goal and exiting.",
                duration / 1000);

        boolean first = true;
        int goalNum = 0;
        ArTime start = new ArTime();
        start.setToNow();
        while (Aria.getRunning()) {
            robot.lock();

            // Choose a new goal if this is the first loop iteration, or if we
            // achieved the previous goal.
            if (first || gotoPoseAction.haveAchievedGoal()) {
                first = false;
                goalNum++;
                if (goalNum > 4) {
                    goalNum = 1; // start again at goal #1
                }

                // set our positions for the different goals
                if (goalNum == 1) {
                    gotoPoseAction.setGoal(new ArPose(2500, 0));
                } else if (goalNum == 2) {
                    gotoPoseAction.setGoal(new ArPose(2500, 2500));
                } else if (goalNum == 3) {
                    gotoPoseAction.setGoal(new ArPose(0, 2500));
                } else if (goalNum == 4) {
                    gotoPoseAction.setGoal(new ArPose(0, 0));
                }

                ArLog.log(ArLog.Normal, "Going to next goal at %.0f %.0f",
                        gotoPoseAction.getGoal().getX(), gotoPoseAction.getGoal().getY());
            }

            if (start.mSecSince() >= duration) {
                ArLog.log(ArLog.Normal, "%d seconds have elapsed. Cancelling current goal, waiting 3 seconds, and"
                        + " exiting.", duration / 1000);
                gotoPoseAction.cancelGoal();
                robot.unlock();
                ArUtil.sleep(3000);
                break;
            }

            robot.unlock();
            ArUtil.sleep(100);
        }

        // Robot disconnected or time elapsed, shut down
        Aria.exit(0);
    }
}
