package robosim.examples.aria;

import robosim.aria.ArActionJoydrive;
import robosim.aria.ArActionKeydrive;
import robosim.aria.ArActionLimiterBackwards;
import robosim.aria.ArActionLimiterForwards;
import robosim.aria.ArActionLimiterTableSensor;
import robosim.aria.ArArgumentParser;
import robosim.aria.ArKeyHandler;
import robosim.aria.ArLog;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.ArSonarDevice;
import robosim.aria.Aria;

/**
 * ARIA's {@code teleopActionsExample.cpp}, line for line: safe teleoperation with actions. Limiters
 * (near and far obstacles ahead, the table sensors, backwards) at the higher priorities keep the
 * joystick and keyboard actions below them from driving the robot into what the sonar sees. The
 * arrow keys drive (each press of up or down steps the speed by 25 mm/s, left and right turn), the
 * space bar stops, Escape exits. RoboSim's robots have no joystick, so only the keys drive.
 *
 * <p>One line more than ARIA's: ARIA's {@code ArActionKeydrive} makes a terminal key handler when
 * the program has none; RoboSim's does not (see ARIA-SEMANTICS.md), so this program makes it, as
 * ARIA's {@code ArActionKeydrive::setRobot} (ArActionKeydrive.cpp) would.
 */
public final class TeleopActionsExample {
    private TeleopActionsExample() {
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
            ArLog.log(ArLog.Terse, "teleopActionsExample: Could not connect to the robot.");
            if (parser.checkHelpAndWarnUnparsed()) {
                Aria.logOptions();
                Aria.exit(1);
            }
        }
        if (!Aria.parseArgs() || !parser.checkHelpAndWarnUnparsed()) {
            Aria.logOptions();
            Aria.exit(1);
        }
        ArLog.log(ArLog.Normal, "teleopActionsExample: Connected.");

        // limiter for close obstacles
        ArActionLimiterForwards limiter = new ArActionLimiterForwards("speed limiter near", 300, 600, 250);
        // limiter for far away obstacles
        ArActionLimiterForwards limiterFar = new ArActionLimiterForwards("speed limiter far", 300, 1100, 400);
        // limiter that checks IR sensors (like Peoplebot has)
        ArActionLimiterTableSensor tableLimiter = new ArActionLimiterTableSensor();
        // limiter so we don't bump things backwards
        ArActionLimiterBackwards backwardsLimiter = new ArActionLimiterBackwards();
        // the joydrive action
        ArActionJoydrive joydriveAct = new ArActionJoydrive();
        // the keydrive action
        ArActionKeydrive keydriveAct = new ArActionKeydrive();

        // sonar device, used by the limiter actions.
        ArSonarDevice sonar = new ArSonarDevice();

        System.out.print("This program will allow you to use a joystick or keyboard to control the robot.\nYou can"
                + " use the arrow keys to drive, and the spacebar to stop.\nFor joystick control press the trigger"
                + " button and then drive.\nPress escape to exit.\n");

        // if we don't have a joystick, let 'em know
        if (!joydriveAct.joystickInited()) {
            System.out.print("Do not have a joystick, only the arrow keys on the keyboard will work.\n");
        }

        // add the sonar to the robot
        robot.addRangeDevice(sonar);

        // set the robots maximum velocity (sonar don't work at all well if you're
        // going faster)
        robot.setAbsoluteMaxTransVel(400);

        // enable the motor
        robot.enableMotors();

        // the key handler ARIA's keydrive action makes for itself when there is none
        ArKeyHandler keyHandler = new ArKeyHandler();
        Aria.setKeyHandler(keyHandler);
        robot.attachKeyHandler(keyHandler);

        // Add the actions, with the limiters as highest priority, then the teleop.
        // actions.  This will keep the teleop. actions from being able to drive too
        // fast and hit something
        robot.addAction(tableLimiter, 100);
        robot.addAction(limiter, 95);
        robot.addAction(limiterFar, 90);
        robot.addAction(backwardsLimiter, 85);
        robot.addAction(joydriveAct, 50);
        robot.addAction(keydriveAct, 45);

        // Configure the joydrive action so it will let the lower priority actions
        // (i.e. keydriveAct) request motion if the joystick button is
        // not pressed.
        joydriveAct.setStopIfNoButtonPressed(false);

        // run the robot, true means that the run will exit if connection lost
        robot.run(true);

        Aria.exit(0);
    }
}
