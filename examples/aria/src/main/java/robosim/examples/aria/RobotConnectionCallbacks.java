package robosim.examples.aria;

import robosim.aria.ArArgumentParser;
import robosim.aria.ArCommands;
import robosim.aria.ArLog;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.ArUtil;
import robosim.aria.Aria;

/**
 * ARIA's {@code robotConnectionCallbacks.cpp}, line for line: a handler whose methods the robot
 * calls when it connects (then it turns the sonar off), when connecting fails, and when the
 * connection closes or is lost (then the program exits). The program sleeps 10 seconds, then asks
 * the robot's cycle to end and exits.
 */
public final class RobotConnectionCallbacks {
    private RobotConnectionCallbacks() {
    }

    /** Reacts to the robot's connection events; C++'s functors are method references. */
    static final class ConnHandler {
        private final ArRobot myRobot;

        /* Adds the handler's methods as the robot's connection callbacks. */
        ConnHandler(ArRobot robot) {
            myRobot = robot;
            myRobot.addConnectCB(this::connected);
            myRobot.addFailedConnectCB(this::connectionFailed);
            myRobot.addDisconnectNormallyCB(this::disconnected);
            myRobot.addDisconnectOnErrorCB(this::disconnected);
        }

        void connectionFailed() {
            ArLog.log(ArLog.Normal, "ConnHandler: Connection failed. Exiting the program.");
            Aria.exit(1);
        }

        void connected() {
            ArLog.log(ArLog.Normal, "ConnHandler: Connected. Turning off sonar,");
            myRobot.comInt(ArCommands.SONAR, 0);
            myRobot.comInt(ArCommands.SOUNDTOG, 0);
        }

        void disconnected() {
            ArLog.log(ArLog.Normal, "ConnHandler: Connection closed. Exiting the program.");
            Aria.exit(0);
        }

        void connectionLost() {
            ArLog.log(ArLog.Normal, "ConnHandler: Lost connection due to an error! Exiting the program!");
            Aria.exit(1);
        }
    }

    /**
     * @param args RoboSim's {@code NAME HOST PORT}, or ARIA's robot arguments ({@code -help})
     */
    public static void main(String[] args) {
        Aria.init();
        ArArgumentParser parser = new ArArgumentParser(args);
        parser.loadDefaultArguments();
        ArRobot robot = new ArRobot();
        ConnHandler ch = new ConnHandler(robot);

        ArRobotConnector robotConnector = new ArRobotConnector(parser, robot);
        if (!robotConnector.connectRobot()) {
            ArLog.log(ArLog.Terse, "robotConnectionCallbacks: Could not connect to the robot.");
            if (parser.checkHelpAndWarnUnparsed()) {
                Aria.logOptions();
                Aria.exit(1);
            }
        }

        if (!Aria.parseArgs() || !parser.checkHelpAndWarnUnparsed()) {
            Aria.logOptions();
            Aria.exit(1);
        }

        ArLog.log(ArLog.Normal, "robotConnectionCallbacks: Connected.");

        robot.runAsync(true);

        // Sleep for 10 seconds, then request that ArRobot stop its thread.
        ArLog.log(ArLog.Normal, "Sleeping for 10 seconds...");
        ArUtil.sleep(10000);
        ArLog.log(ArLog.Normal, "...requesting that the robot thread exit, then shutting down ARIA and exiting.");
        robot.stopRunning();
        Aria.exit(0);
    }
}
