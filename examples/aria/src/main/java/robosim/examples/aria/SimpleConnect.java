package robosim.examples.aria;

import robosim.aria.ArArgumentParser;
import robosim.aria.ArLog;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.ArUtil;
import robosim.aria.Aria;

/**
 * ARIA's {@code simpleConnect.cpp}, line for line: one of the simplest ARIA programs. It connects
 * with {@link ArRobotConnector}, prints the pose, velocity and battery, waits 3 seconds doing
 * nothing, then exits.
 *
 * <p>It runs against a RoboSim Environment ({@code robosim robot robosim.examples.aria.SimpleConnect
 * r1 HOST PORT}), RoboSim's Pioneer port or MobileSim ({@code -remoteHost HOST -remoteRobotTcpPort
 * PORT}), as the C++ does.
 */
public final class SimpleConnect {
    private SimpleConnect() {
    }

    /**
     * @param args RoboSim's {@code NAME HOST PORT}, or ARIA's robot arguments ({@code -help} lists them)
     */
    public static void main(String[] args) {
        Aria.init();
        ArArgumentParser parser = new ArArgumentParser(args);
        parser.loadDefaultArguments();
        ArRobot robot = new ArRobot();

        // Connect to the robot, get some initial data from it such as type and name,
        // and then load parameter files for this robot.
        ArRobotConnector robotConnector = new ArRobotConnector(parser, robot);
        if (!robotConnector.connectRobot()) {
            ArLog.log(ArLog.Terse, "simpleConnect: Could not connect to the robot.");
            if (parser.checkHelpAndWarnUnparsed()) {
                // -help not given
                Aria.logOptions();
                Aria.exit(1);
            }
        }

        if (!Aria.parseArgs() || !parser.checkHelpAndWarnUnparsed()) {
            Aria.logOptions();
            Aria.exit(1);
        }

        ArLog.log(ArLog.Normal, "simpleConnect: Connected to robot.");

        robot.enableMotors();

        // Start the robot processing cycle running in the background.
        // True parameter means that if the connection is lost, then the
        // run loop ends.
        robot.runAsync(true);

        // Print out some data from the SIP. We must "lock" the ArRobot object
        // before calling its methods, and "unlock" when done, to prevent conflicts
        // with the background thread started by the call to robot.runAsync() above.
        robot.lock();
        boolean soc = robot.hasStateOfCharge();
        double batt;
        if (soc) {
            batt = robot.getStateOfCharge();
        } else {
            batt = robot.getBatteryVoltage();
        }
        ArLog.log(ArLog.Normal, "simpleConnect: Pose=(%.2f,%.2f,%.2f), Trans.  Vel=%.2f, Battery=%.2f%c",
                robot.getX(), robot.getY(), robot.getTh(), robot.getVel(), batt, soc ? '%' : 'V');
        robot.unlock();

        // Sleep for 3 seconds.
        ArLog.log(ArLog.Normal, "simpleConnect: Sleeping for 3 seconds...");
        ArUtil.sleep(3000);

        ArLog.log(ArLog.Normal, "simpleConnect: Ending robot thread...");
        robot.stopRunning();

        // wait for the thread to stop
        robot.waitForRunExit();

        // exit
        ArLog.log(ArLog.Normal, "simpleConnect: Exiting.");
        Aria.exit(0);
    }
}
