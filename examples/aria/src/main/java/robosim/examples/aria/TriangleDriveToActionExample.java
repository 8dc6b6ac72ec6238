package robosim.examples.aria;

import robosim.aria.ArActionKeydrive;
import robosim.aria.ArActionLimiterBackwards;
import robosim.aria.ArActionLimiterForwards;
import robosim.aria.ArActionStop;
import robosim.aria.ArActionTriangleDriveTo;
import robosim.aria.ArArgumentParser;
import robosim.aria.ArCommands;
import robosim.aria.ArKeyHandler;
import robosim.aria.ArLaserConnector;
import robosim.aria.ArLog;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.Aria;

/**
 * ARIA's {@code triangleDriveToActionExample.cpp}, line for line: {@link ArActionTriangleDriveTo}
 * drives the robot up to a triangular target its laser sees (by default two faces of at least
 * 250 mm meeting at 135 degrees, the vertex towards the robot), stopping 400 mm out from the
 * vertex, facing it. Press g or G to find and drive to the target, s or S to stop; the arrow keys
 * drive when it is stopped, under a forwards and a backwards limiter. It needs the laser
 * ({@code -connectLaser}).
 */
public final class TriangleDriveToActionExample {
    private TriangleDriveToActionExample() {
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
            ArLog.log(ArLog.Terse, "triangleDriveToActionExample: Could not connect to the robot.");
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

        ArLog.log(ArLog.Normal, "triangleDriveToActionExample: Connected to robot.");

        if (!laserConnector.connectLasers()) {
            ArLog.log(ArLog.Terse, "triangleDriveToActionExample: Could not connect to laser(s).  Exiting.");
            Aria.exit(3);
            return;
        }
        ArLog.log(ArLog.Normal, "Connected to laser.");

        ArKeyHandler keyHandler = new ArKeyHandler();
        Aria.setKeyHandler(keyHandler);
        robot.attachKeyHandler(keyHandler);

        ArActionTriangleDriveTo triangleDriveTo = new ArActionTriangleDriveTo();
        Runnable lineGoCB = triangleDriveTo::activate;
        keyHandler.addKeyHandler('g', lineGoCB);
        keyHandler.addKeyHandler('G', lineGoCB);
        Runnable lineStopCB = triangleDriveTo::deactivate;
        keyHandler.addKeyHandler('s', lineStopCB);
        keyHandler.addKeyHandler('S', lineStopCB);

        ArActionLimiterForwards limiter = new ArActionLimiterForwards("limiter", 150, 0, 0, 1.3);
        robot.addAction(limiter, 70);
        ArActionLimiterBackwards limiterBackwards = new ArActionLimiterBackwards();
        robot.addAction(limiterBackwards, 69);

        robot.addAction(triangleDriveTo, 60);

        ArActionKeydrive keydrive = new ArActionKeydrive();
        robot.addAction(keydrive, 55);

        ArActionStop stopAction = new ArActionStop();
        robot.addAction(stopAction, 50);

        robot.comInt(ArCommands.SONAR, 1);
        robot.comInt(ArCommands.ENABLE, 1);

        // start the robot running, true so that if we lose connection the run stops
        robot.runAsync(true);

        System.out.print("press the 'g' key to locate a triangle shape, press 's' to stop teh robot.\n");

        robot.waitForRunExit();
        Aria.exit(0);
    }
}
