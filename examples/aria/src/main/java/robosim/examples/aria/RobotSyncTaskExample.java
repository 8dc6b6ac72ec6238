package robosim.examples.aria;

import robosim.aria.ArArgumentParser;
import robosim.aria.ArLog;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.Aria;

/**
 * ARIA's {@code robotSyncTaskExample.cpp}, line for line: a task the robot runs every cycle, as a
 * sensor-interpretation task, printing the robot's pose, velocity and motor packets per second on
 * one line, until the robot is disconnected. A task must take little time, not to delay the cycle.
 */
public final class RobotSyncTaskExample {
    private RobotSyncTaskExample() {
    }

    /** Prints the robot's state each cycle. */
    static final class PrintingTask {
        private final ArRobot myRobot;
        private final Runnable myTaskCB = this::doTask;

        /* Adds its task to the robot's sensor-interpretation tasks. */
        PrintingTask(ArRobot robot) {
            myRobot = robot;
            myRobot.addSensorInterpTask("PrintingTask", 50, myTaskCB);
        }

        /* ARIA's destructor: removes the task. */
        void close() {
            myRobot.remSensorInterpTask(myTaskCB);
        }

        void doTask() {
            System.out.printf("\rx %6.1f  y %6.1f  th  %6.1f vel %7.1f mpacs %3d", myRobot.getX(), myRobot.getY(),
                    myRobot.getTh(), myRobot.getVel(), myRobot.getMotorPacCount());
            System.out.flush();
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

        ArRobotConnector robotConnector = new ArRobotConnector(parser, robot);
        if (!robotConnector.connectRobot()) {
            ArLog.log(ArLog.Terse, "robotSyncTaskExample: Could not connect to the robot.");
            if (parser.checkHelpAndWarnUnparsed()) {
                Aria.logOptions();
                Aria.exit(1);
            }
        }
        if (!Aria.parseArgs() || !parser.checkHelpAndWarnUnparsed()) {
            Aria.logOptions();
            Aria.exit(1);
        }

        ArLog.log(ArLog.Normal, "robotSyncTaskExample: Connected to robot.");

        PrintingTask pt = new PrintingTask(robot);

        // Run the robot's cycle in this thread until the robot is disconnected.
        robot.run(true);
        pt.close();

        System.out.printf("Disconnected. Goodbye.%n");
    }
}
