package robosim.examples.aria;

import java.util.List;
import java.util.Map;
import robosim.aria.ArArgumentParser;
import robosim.aria.ArLaser;
import robosim.aria.ArLaserConnector;
import robosim.aria.ArLog;
import robosim.aria.ArPoseWithTime;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.ArUtil;
import robosim.aria.Aria;

/**
 * ARIA's {@code laserConnect.cpp}, line for line: connects the robot and the lasers the command
 * line asks for ({@code -connectLaser}), then every 5 seconds prints, for each laser, how many
 * current readings it has and where its closest reading is, until the robot is disconnected.
 */
public final class LaserConnect {
    private LaserConnect() {
    }

    /**
     * @param args RoboSim's {@code NAME HOST PORT}, or ARIA's robot arguments, and ARIA's laser
     *             arguments ({@code -connectLaser}; {@code -help} lists them)
     */
    public static void main(String[] args) {
        Aria.init();
        ArRobot robot = new ArRobot();
        ArArgumentParser parser = new ArArgumentParser(args);
        parser.loadDefaultArguments();
        ArRobotConnector robotConnector = new ArRobotConnector(parser, robot);
        ArLaserConnector laserConnector = new ArLaserConnector(parser, robot, robotConnector);

        // Connect to the robot, get some initial data from it such as type and name,
        // and then load parameter files for this robot.
        if (!robotConnector.connectRobot()) {
            ArLog.log(ArLog.Terse, "lasersExample: Could not connect to the robot.");
            if (parser.checkHelpAndWarnUnparsed()) {
                // -help not given
                Aria.logOptions();
                Aria.exit(1);
            }
        }

        if (!Aria.parseArgs()) {
            Aria.logOptions();
            Aria.exit(2);
            return;
        }

        ArLog.log(ArLog.Normal, "lasersExample: Connected to robot.");

        // Start the robot processing cycle running in the background.
        // True parameter means that if the connection is lost, then the
        // run loop ends.
        robot.runAsync(true);

        // Connect to laser(s) as defined in parameter files.
        if (!laserConnector.connectLasers()) {
            ArLog.log(ArLog.Terse, "Could not connect to configured lasers. Exiting.");
            Aria.exit(3);
            return;
        }

        // Allow some time to read laser data
        ArUtil.sleep(500);

        ArLog.log(ArLog.Normal, "Connected to all lasers.");

        // Print out some data from each connected laser.
        while (robot.isConnected()) {
            int numLasers = 0;

            // Get ArRobot's lasers. Lock the robot while using it to prevent changes by tasks in the
            // robot's cycle or any other threads.
            robot.lock();
            Map<Integer, ArLaser> lasers = robot.getLaserMap();

            for (Map.Entry<Integer, ArLaser> i : lasers.entrySet()) {
                int laserIndex = i.getKey();
                ArLaser laser = i.getValue();
                if (laser == null) {
                    continue;
                }
                ++numLasers;
                laser.lockDevice();

                // The current readings are a set of obstacle readings (with X,Y positions as well as
                // other attributes) that are the most recent set from the laser.
                List<ArPoseWithTime> currentReadings = laser.getCurrentReadings(); // see ArRangeDevice

                // There is a utility to find the closest reading within a range of degrees around the
                // laser, here we use this laser's full field of view (start to end). If there are no
                // valid closest readings within the given range, dist will be greater than
                // laser.getMaxRange().
                double[] angle = {0};
                double dist = laser.currentReadingPolar(laser.getStartDegrees(), laser.getEndDegrees(), angle);

                ArLog.log(ArLog.Normal, "Laser #%d (%s): %s. Have %d 'current' readings. Closest reading is at %3.0f"
                        + " degrees and is %2.4f meters away.", laserIndex, laser.getName(),
                        laser.isConnected() ? "connected" : "NOT CONNECTED", currentReadings.size(), angle[0],
                        dist / 1000.0);
                laser.unlockDevice();
            }
            if (numLasers == 0) {
                ArLog.log(ArLog.Normal, "No lasers.");
            } else {
                ArLog.log(ArLog.Normal, "");
            }

            // Unlock robot and sleep for 5 seconds before next loop.
            robot.unlock();
            ArUtil.sleep(5000);
        }

        ArLog.log(ArLog.Normal, "lasersExample: exiting.");
        Aria.exit(0);
    }
}
