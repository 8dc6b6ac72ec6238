package robosim.examples.aria;

import robosim.aria.ArActionAvoidFront;
import robosim.aria.ArActionBumpers;
import robosim.aria.ArActionConstantVelocity;
import robosim.aria.ArActionGroup;
import robosim.aria.ArActionJoydrive;
import robosim.aria.ArActionKeydrive;
import robosim.aria.ArActionLimiterBackwards;
import robosim.aria.ArActionLimiterForwards;
import robosim.aria.ArActionLimiterTableSensor;
import robosim.aria.ArActionStallRecover;
import robosim.aria.ArArgumentParser;
import robosim.aria.ArKeyHandler;
import robosim.aria.ArLog;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.ArSonarDevice;
import robosim.aria.Aria;

/**
 * ARIA's {@code actionGroupExample.cpp}, line for line: two action groups, teleoperation (limiters
 * for near and far obstacles ahead and behind, above the joystick and the keyboard's arrow keys)
 * and wander (stall recovery, bumpers, avoiding what is ahead, a constant 400 mm/s), and the keys
 * {@code t} and {@code w} to switch between them: each activates its group exclusively, so the
 * other's actions stop. It starts in teleoperation; Escape (or the end of the run) ends it.
 */
public final class ActionGroupExample {
    private static ArActionGroup teleop;
    private static ArActionGroup wander;

    private ActionGroupExample() {
    }

    // Activate the teleop action group. activateExclusive() causes
    // all other active action groups to be deactivated.
    static void teleopMode() {
        teleop.activateExclusive();
        System.out.printf("\n== Teleoperation Mode ==\n");
        System.out.printf("   Use the arrow keys to drive, and the spacebar to stop.\n    For joystick control hold the"
                + " trigger button.\n    Press 'w' to switch to wander mode.\n    Press escape to exit.\n");
    }

    // Activate the wander action group. activateExclusive() causes
    // all other active action groups to be deactivated.
    static void wanderMode() {
        wander.activateExclusive();
        System.out.printf("\n== Wander Mode ==\n");
        System.out.printf("    The robot will now just wander around avoiding things.\n    Press 't' to switch to "
                + " teleop mode.\n    Press escape to exit.\n");
    }

    /**
     * @param args RoboSim's {@code NAME HOST PORT}, or ARIA's robot arguments ({@code -help})
     */
    public static void main(String[] args) {
        Aria.init();
        ArArgumentParser parser = new ArArgumentParser(args);
        parser.loadDefaultArguments();
        ArRobot robot = new ArRobot();
        ArSonarDevice sonar = new ArSonarDevice();

        // Connect to the robot, get some initial data from it such as type and name,
        // and then load parameter files for this robot.
        ArRobotConnector robotConnector = new ArRobotConnector(parser, robot);
        if (!robotConnector.connectRobot()) {
            ArLog.log(ArLog.Terse, "actionGroupExample: Could not connect to the robot.");
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

        ArLog.log(ArLog.Normal, "actionGroupExample: Connected to robot.");

        /* - the action group for teleoperation actions: */
        teleop = new ArActionGroup(robot);

        // don't hit any tables (if the robot has IR table sensors)
        teleop.addAction(new ArActionLimiterTableSensor(), 100);

        // limiter for close obstacles
        teleop.addAction(new ArActionLimiterForwards("speed limiter near", 300, 600, 250), 95);

        // limiter for far away obstacles
        teleop.addAction(new ArActionLimiterForwards("speed limiter far", 300, 1100, 400), 90);

        // limiter so we don't bump things backwards
        teleop.addAction(new ArActionLimiterBackwards(), 85);

        // the joydrive action (drive from joystick)
        ArActionJoydrive joydriveAct = new ArActionJoydrive("joydrive", 400, 15);
        teleop.addAction(joydriveAct, 50);

        // the keydrive action (drive from keyboard)
        teleop.addAction(new ArActionKeydrive(), 45);

        /* - the action group for wander actions: */
        wander = new ArActionGroup(robot);

        // if we're stalled we want to back up and recover
        wander.addAction(new ArActionStallRecover(), 100);

        // react to bumpers
        wander.addAction(new ArActionBumpers(), 75);

        // turn to avoid things closer to us
        wander.addAction(new ArActionAvoidFront("Avoid Front Near", 225, 0), 50);

        // turn avoid things further away
        wander.addAction(new ArActionAvoidFront(), 45);

        // keep moving
        wander.addAction(new ArActionConstantVelocity("Constant Velocity", 400), 25);

        /* - use key commands to switch modes, and use keyboard
         *   and joystick as inputs for teleoperation actions. */

        // create key handler if Aria does not already have one
        ArKeyHandler keyHandler = Aria.getKeyHandler();
        if (keyHandler == null) {
            keyHandler = new ArKeyHandler();
            Aria.setKeyHandler(keyHandler);
            robot.attachKeyHandler(keyHandler);
        }

        // set the callbacks
        Runnable teleopCB = ActionGroupExample::teleopMode;
        Runnable wanderCB = ActionGroupExample::wanderMode;
        keyHandler.addKeyHandler('w', wanderCB);
        keyHandler.addKeyHandler('W', wanderCB);
        keyHandler.addKeyHandler('t', teleopCB);
        keyHandler.addKeyHandler('T', teleopCB);

        // if we don't have a joystick, let 'em know
        if (!joydriveAct.joystickInited()) {
            System.out.printf("Note: Do not have a joystick, only the arrow keys on the keyboard will work.\n");
        }

        // set the joystick so it won't do anything if the button isn't pressed
        joydriveAct.setStopIfNoButtonPressed(false);

        /* - connect to the robot, then enter teleoperation mode.  */

        robot.addRangeDevice(sonar);

        robot.enableMotors();
        teleopMode();
        robot.run(true);

        Aria.exit(0);
    }
}
