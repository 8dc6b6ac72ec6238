package robosim.examples.aria;

import robosim.aria.ArArgumentParser;
import robosim.aria.ArKeyHandler;
import robosim.aria.ArLaser;
import robosim.aria.ArLaserConnector;
import robosim.aria.ArLineFinder;
import robosim.aria.ArLog;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.Aria;

/**
 * ARIA's {@code lineFinderExample.cpp}, line for line: an {@link ArLineFinder} on the robot's first
 * laser; the {@code f} key finds the lines in the latest scan and saves them, with the scan's points,
 * to the files {@code points} and {@code lines} in the working directory. Escape (or the end of the
 * run) ends it.
 */
public final class LineFinderExample {
    private LineFinderExample() {
    }

    /**
     * @param args RoboSim's {@code NAME HOST PORT}, or ARIA's robot and laser arguments ({@code -help})
     */
    public static void main(String[] args) {
        Aria.init();
        ArArgumentParser parser = new ArArgumentParser(args);
        parser.loadDefaultArguments();
        ArRobot robot = new ArRobot();
        ArRobotConnector robotConnector = new ArRobotConnector(parser, robot);
        ArLaserConnector laserConnector = new ArLaserConnector(parser, robot, robotConnector);

        if (!robotConnector.connectRobot()) {
            ArLog.log(ArLog.Terse, "lineFinderExample: Could not connect to the robot.");
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

        ArLog.log(ArLog.Normal, "lineFinderExample: Connected to robot.");

        robot.runAsync(true);

        // Connect to laser(s) as defined in parameter files.
        if (!laserConnector.connectLasers()) {
            ArLog.log(ArLog.Terse, "Could not connect to configured lasers. Exiting.");
            Aria.exit(3);
            return;
        }

        ArLog.log(ArLog.Normal, "lineFinderExample: Connected to laser");

        ArKeyHandler keyHandler = new ArKeyHandler();
        Aria.setKeyHandler(keyHandler);
        robot.attachKeyHandler(keyHandler);

        // Create the ArLineFinder object. Set it to log lots of information about its processing.
        ArLaser laser = robot.findLaser(1);
        if (laser == null) {
            ArLog.log(ArLog.Terse, "lineFinderExample: No laser device connected, exiting.");
            Aria.exit(4);
            return;
        }

        ArLineFinder lineFinder = new ArLineFinder(laser);
        lineFinder.setVerbose(true);

        // Add key callbacks that simply call ArLineFinder.getLinesAndSaveThem(), which searches for
        // lines in the current set of laser sensor readings, and saves them in files with the names
        // 'points' and 'lines'.
        Runnable findLineCB = lineFinder::getLinesAndSaveThem;
        keyHandler.addKeyHandler('f', findLineCB);
        keyHandler.addKeyHandler('F', findLineCB);

        System.out.print("If you press the 'f' key the points and lines found will be saved\n");
        System.out.print("Into the 'points' and 'lines' file in the current working directory\n");

        robot.waitForRunExit();
        Aria.exit(0);
    }
}
