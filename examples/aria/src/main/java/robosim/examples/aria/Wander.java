package robosim.examples.aria;

import robosim.aria.ArActionAvoidFront;
import robosim.aria.ArActionBumpers;
import robosim.aria.ArActionConstantVelocity;
import robosim.aria.ArActionStallRecover;
import robosim.aria.ArArgumentParser;
import robosim.aria.ArCommands;
import robosim.aria.ArKeyHandler;
import robosim.aria.ArLaserConnector;
import robosim.aria.ArLog;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.ArSonarDevice;
import robosim.aria.Aria;

/**
 * ARIA's {@code wander.cpp}, line for line: the robot wanders, driven by actions: stall recovery,
 * bumpers, avoiding what is near and far ahead, and a constant forward velocity. The laser is used
 * too when {@code -connectLaser} is given. Escape (or the end of the run) ends it.
 */
public final class Wander {
    private Wander() {
    }

    /**
     * @param args RoboSim's {@code NAME HOST PORT}, or ARIA's robot and laser arguments ({@code -help})
     */
    public static void main(String[] args) {
        Aria.init();
        ArArgumentParser argParser = new ArArgumentParser(args);
        argParser.loadDefaultArguments();
        ArRobot robot = new ArRobot();
        ArRobotConnector robotConnector = new ArRobotConnector(argParser, robot);
        ArLaserConnector laserConnector = new ArLaserConnector(argParser, robot, robotConnector);

        if (!robotConnector.connectRobot()) {
            ArLog.log(ArLog.Terse, "Could not connect to the robot.");
            if (argParser.checkHelpAndWarnUnparsed()) {
                // -help not given, just exit.
                Aria.logOptions();
                Aria.exit(1);
                return;
            }
        }

        // Trigger argument parsing
        if (!Aria.parseArgs() || !argParser.checkHelpAndWarnUnparsed()) {
            Aria.logOptions();
            Aria.exit(1);
            return;
        }

        ArKeyHandler keyHandler = new ArKeyHandler();
        Aria.setKeyHandler(keyHandler);
        robot.attachKeyHandler(keyHandler);

        System.out.println("This program will make the robot wander around. It uses some avoidance\n"
                + "actions if obstacles are detected, otherwise it just has a\n"
                + "constant forward velocity.\n\nPress CTRL-C or Escape to exit.");

        ArSonarDevice sonar = new ArSonarDevice();
        robot.addRangeDevice(sonar);

        robot.runAsync(true);

        // try to connect to laser. if fail, warn but continue, using sonar only
        if (!laserConnector.connectLasers()) {
            ArLog.log(ArLog.Normal, "Warning: unable to connect to requested lasers, will wander using robot sonar only.");
        }

        // turn on the motors, turn off amigobot sounds
        robot.enableMotors();
        robot.comInt(ArCommands.SOUNDTOG, 0);

        // add a set of actions that combine together to effect the wander behavior
        ArActionStallRecover recover = new ArActionStallRecover();
        ArActionBumpers bumpers = new ArActionBumpers();
        ArActionAvoidFront avoidFrontNear = new ArActionAvoidFront("Avoid Front Near", 225, 0);
        ArActionAvoidFront avoidFrontFar = new ArActionAvoidFront();
        ArActionConstantVelocity constantVelocity = new ArActionConstantVelocity("Constant Velocity", 400);
        robot.addAction(recover, 100);
        robot.addAction(bumpers, 75);
        robot.addAction(avoidFrontNear, 50);
        robot.addAction(avoidFrontFar, 49);
        robot.addAction(constantVelocity, 25);

        // wait for robot task loop to end before exiting the program
        robot.waitForRunExit();

        Aria.exit(0);
    }
}
