package robosim.examples.aria;

import robosim.aria.ArActionJoydrive;
import robosim.aria.ArActionKeydrive;
import robosim.aria.ArActionLimiterBackwards;
import robosim.aria.ArActionLimiterForwards;
import robosim.aria.ArActionLimiterTableSensor;
import robosim.aria.ArArgumentParser;
import robosim.aria.ArGripper;
import robosim.aria.ArKeyHandler;
import robosim.aria.ArLog;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.Aria;

/**
 * ARIA's {@code gripperExample.cpp}, line for line: the Pioneer 2-DOF gripper worked from the
 * keyboard while the arrow keys (or a joystick) drive the robot, with ARIA's limiters keeping it
 * off obstacles; every cycle a user task logs the gripper's state ({@code ArGripper::logState}).
 * Keys: {@code u} or Page Up lifts the gripper, {@code d} or Page Down lowers it, {@code o} opens
 * the paddles, {@code c} closes them, {@code s} stops both ({@code gripperHalt}); Escape exits.
 * A robot without a gripper ends the program with ARIA's error. One line more than ARIA's: it makes
 * the key handler ARIA's keydrive action makes for itself (RoboSim's keydrive makes none).
 */
public final class GripperExample {
    private GripperExample() {
    }

    /** Adds a robot task that prints the gripper's status (the C++'s {@code PrintGripStatus}). */
    static final class PrintGripStatus {
        private final ArGripper myGripper;
        private final Runnable myPrintCB;

        PrintGripStatus(ArGripper gripper) {
            myGripper = gripper;
            myPrintCB = this::printStatus;
        }

        void addRobotTask(ArRobot robot) {
            robot.addUserTask("PrintGripStatus", 10, myPrintCB);
        }

        void printStatus() {
            myGripper.logState();
        }
    }

    /** Adds key handlers that work the gripper (the C++'s {@code GripperControlHandler}). */
    static final class GripperControlHandler {
        private final ArGripper myGripper;
        private final Runnable myUpCB;
        private final Runnable myDownCB;
        private final Runnable myOpenCB;
        private final Runnable myCloseCB;
        private final Runnable myStopCB;

        GripperControlHandler(ArGripper gripper) {
            myGripper = gripper;
            myUpCB = this::liftUp;
            myDownCB = this::liftDown;
            myOpenCB = this::open;
            myCloseCB = this::close;
            myStopCB = this::stop;
        }

        void addKeyHandlers(ArRobot robot) {
            ArKeyHandler keyHandler = Aria.getKeyHandler();
            if (keyHandler == null) {
                keyHandler = new ArKeyHandler();
                Aria.setKeyHandler(keyHandler);
                robot.attachKeyHandler(keyHandler);
            }
            keyHandler.addKeyHandler(ArKeyHandler.PAGEUP, myUpCB);
            keyHandler.addKeyHandler('u', myUpCB);
            keyHandler.addKeyHandler(ArKeyHandler.PAGEDOWN, myDownCB);
            keyHandler.addKeyHandler('d', myDownCB);
            keyHandler.addKeyHandler('o', myOpenCB);
            keyHandler.addKeyHandler('c', myCloseCB);
            keyHandler.addKeyHandler('s', myStopCB);
        }

        void liftUp() {
            ArLog.log(ArLog.Normal, "Moving gripper lift up...");
            myGripper.liftUp();
        }

        void liftDown() {
            ArLog.log(ArLog.Normal, "Moving gripper lift down...");
            myGripper.liftDown();
        }

        void stop() {
            ArLog.log(ArLog.Normal, "Stopping gripper...");
            myGripper.gripperHalt(); // stops both lift an grip
        }

        void close() {
            ArLog.log(ArLog.Normal, "Closing gripper...");
            myGripper.gripClose();
        }

        void open() {
            ArLog.log(ArLog.Normal, "Opening gripper...");
            myGripper.gripOpen();
        }
    }

    /**
     * @param args RoboSim's {@code NAME HOST PORT}, or ARIA's robot arguments ({@code -help} lists them)
     */
    public static void main(String[] args) {
        Aria.init();
        ArArgumentParser parser = new ArArgumentParser(args);
        parser.loadDefaultArguments();
        ArRobot robot = new ArRobot();
        ArGripper gripper = new ArGripper(robot);

        // Connect to the robot, get some initial data from it such as type and name,
        // and then load parameter files for this robot.
        ArRobotConnector robotConnector = new ArRobotConnector(parser, robot);
        if (!robotConnector.connectRobot()) {
            ArLog.log(ArLog.Terse, "gripperExample: Could not connect to the robot.");
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

        ArLog.log(ArLog.Normal, "gripperExample: Connected to robot.");

        ArLog.log(ArLog.Normal, "gripperExample: GripperType=%d", gripper.getType().ordinal());
        gripper.logState();
        if (gripper.getType() == ArGripper.Type.NOGRIPPER) {
            ArLog.log(ArLog.Terse, "gripperExample: Error: Robot does not have a gripper. Exiting.");
            Aria.exit(-1);
            return;
        }

        // Teleoperation actions with obstacle-collision avoidance
        ArActionLimiterTableSensor tableLimit = new ArActionLimiterTableSensor();
        robot.addAction(tableLimit, 110);
        ArActionLimiterForwards limitNearAction = new ArActionLimiterForwards("near", 300, 600, 250);
        robot.addAction(limitNearAction, 100);
        ArActionLimiterForwards limitFarAction = new ArActionLimiterForwards("far", 300, 1100, 400);
        robot.addAction(limitFarAction, 90);
        ArActionLimiterBackwards limitBackAction = new ArActionLimiterBackwards();
        robot.addAction(limitBackAction, 50);
        ArActionJoydrive joydriveAction = new ArActionJoydrive("joydrive", 400, 15);
        robot.addAction(joydriveAction, 40);
        joydriveAction.setStopIfNoButtonPressed(false);
        // the key handler ARIA's keydrive action makes for itself when there is none
        if (Aria.getKeyHandler() == null) {
            ArKeyHandler keyHandler = new ArKeyHandler();
            Aria.setKeyHandler(keyHandler);
            robot.attachKeyHandler(keyHandler);
        }
        ArActionKeydrive keydriveAction = new ArActionKeydrive();
        robot.addAction(keydriveAction, 30);

        // Handlers to control the gripper and print out info (classes defined above)
        PrintGripStatus printStatus = new PrintGripStatus(gripper);
        GripperControlHandler gripControl = new GripperControlHandler(gripper);
        printStatus.addRobotTask(robot);
        gripControl.addKeyHandlers(robot);

        // enable motors and run (if we lose connection to the robot, exit)
        ArLog.log(ArLog.Normal, "You may now operate the robot with arrow keys or joystick. Operate the gripper"
                + " with the u, d, o, c, and page up/page down keys.");
        robot.enableMotors();
        robot.run(true);

        Aria.exit(0);
    }
}
