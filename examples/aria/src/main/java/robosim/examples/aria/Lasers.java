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
import robosim.aria.ArSensorReading;
import robosim.aria.ArUtil;
import robosim.aria.Aria;
import robosim.protocol.RobotParameters;

/**
 * ARIA's {@code lasers.cpp}, line for line: connects the robot and the lasers its parameter file and
 * command line enable ({@code -connectLaser}), logs the lasers' parameters and the connector's
 * settings, then every 3 seconds, for each laser of the robot, how many current and raw readings it
 * has and where its closest reading is, until the robot is disconnected.
 *
 * <p>RoboSim simulates one laser, laser 1, mounted where the robot's parameter file says; a second
 * laser ({@code -laserType2}) is refused by {@link ArLaserConnector} with the reason, as ARIA refuses
 * a laser it cannot make.
 */
public final class Lasers {
    private Lasers() {
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

        if (!Aria.parseArgs() || !parser.checkHelpAndWarnUnparsed()) {
            Aria.logOptions();
            Aria.exit(2);
            return;
        }

        ArLog.log(ArLog.Normal, "lasersExample: Connected to robot.");

        // Start the robot processing cycle running in the background.
        // True parameter means that if the connection is lost, then the
        // run loop ends.
        robot.runAsync(true);

        // Connect to laser(s) defined in parameter files, if LaserAutoConnect is true
        // for the laser (in RoboSim: if -connectLaser is given).
        ArLog.log(ArLog.Normal, "lasersExample: Connecting to any lasers enabled for connect...");
        if (!laserConnector.connectLasers()) {
            ArLog.log(ArLog.Terse, "lasersExample: Could not connect to configured lasers. Exiting.");
            Aria.exit(3);
            return;
        }
        ArLog.log(ArLog.Normal, "lasersExample: Connected to all lasers.\n");

        // Log parameters related to the lasers. RoboSim's parameters mount one laser (laser 1) and
        // give it no height (ARIA's 0, unknown) and no power output.
        ArLog.log(ArLog.Normal, "\nlasersExample: Robot parameters include information for %d lasers:",
                robot.getNumLasers());
        RobotParameters params = robot.getRobotParams();
        for (int i = 1; i <= robot.getNumLasers(); ++i) {
            if (robot.findLaser(i) == null) {
                continue;
            }
            ArLog.log(ArLog.Normal, "\tlaser #%d: pose=(x:%d, y:%d, z:%d, th:%.2f), powerOutput=%s",
                    i,
                    Math.round(params.laserX()), Math.round(params.laserY()), 0, params.laserTh(),
                    "");
        }
        ArLog.log(ArLog.Normal, "lasersExample: ArLaserConnector also using the following parameters (if values"
                + " given, otherwise defaults for this laser type will be used):");
        laserConnector.logLaserData();
        ArLog.log(ArLog.Normal, "");

        // Allow some time to read laser data
        ArUtil.sleep(500);

        // Print out some data from each connected laser.
        while (robot.isConnected()) {
            int numLasers = 0;

            // Get ArRobot's lasers. Lock the robot while using it to prevent changes by tasks in the
            // robot's background task thread or any other threads. Each laser has an index; its
            // index or name (laser.getName()) finds it again with ArRobot.findLaser().
            robot.lock();
            Map<Integer, ArLaser> lasers = robot.getLaserMap();

            ArLog.log(ArLog.Normal, "lasersExample: ArRobot provided a set of %d ArLaser objects.", lasers.size());

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

                // The raw readings are just range or other data supplied by the sensor. Most laser
                // devices provide raw readings, but some may not, so this may be null or empty.
                List<ArSensorReading> rawReadings = laser.getRawReadings();

                // There is a utility to find the closest reading within a range of degrees around the
                // laser, here we use this laser's full field of view (start to end). If there are no
                // valid closest readings within the given range, dist will be greater than
                // laser.getMaxRange().
                double[] angle = {0};
                double dist = laser.currentReadingPolar(laser.getStartDegrees(), laser.getEndDegrees(), angle);

                ArLog.log(ArLog.Normal, "lasersExample: Laser #%d (%s): %s.\n\tHave %d 'current' readings.\n\tHave"
                        + " %d 'raw' readings.\n\tClosest reading is at %3.0f degrees and is %2.4f meters away.",
                        laserIndex, laser.getName(), laser.isConnected() ? "connected" : "NOT CONNECTED",
                        currentReadings.size(),
                        rawReadings != null ? rawReadings.size() : 0,
                        angle[0], dist / 1000.0);

                laser.unlockDevice();
            }
            if (numLasers == 0) {
                ArLog.log(ArLog.Normal, "lasersExample: No lasers.");
            } else {
                ArLog.log(ArLog.Normal, "");
            }

            // Unlock robot and sleep for a few seconds before next loop.
            robot.unlock();
            ArUtil.sleep(3000);
        }

        ArLog.log(ArLog.Normal, "lasersExample: exiting.");
        Aria.exit(0);
    }
}
