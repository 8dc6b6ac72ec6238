package robosim.examples.aria;

import robosim.aria.ArAction;
import robosim.aria.ArActionDesired;
import robosim.aria.ArActionStallRecover;
import robosim.aria.ArArg;
import robosim.aria.ArArgumentParser;
import robosim.aria.ArLog;
import robosim.aria.ArRangeDevice;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.ArSonarDevice;
import robosim.aria.Aria;

/**
 * ARIA's {@code actionExample.cpp}, line for line: two new actions, Go (drives forward, slowing as
 * the sonar sees something ahead, stopping 350 mm from it) and Turn (turns away from what the
 * sonar sees within 400 mm on either side), with ARIA's stall recovery above them.
 */
public final class ActionExample {
    private ActionExample() {
    }

    /** Action that drives the robot forward, but stops if obstacles are detected by sonar. */
    static final class ActionGo extends ArAction {
        private ArRangeDevice mySonar;
        /* Our current desired action: fire() modifies this object and returns it to the resolver. */
        private final ArActionDesired myDesired = new ArActionDesired();
        private double myMaxSpeed;
        private double myStopDistance;

        /*
         * Note how it uses setNextArgument, which makes it so that other parts of the program could
         * find out what parameters this action has, and possibly modify them.
         */
        ActionGo(double maxSpeed, double stopDistance) {
            super("Go");
            mySonar = null;
            myMaxSpeed = maxSpeed;
            myStopDistance = stopDistance;
            setNextArgument(ArArg.ofDouble("maximum speed", () -> myMaxSpeed, v -> myMaxSpeed = v, "Maximum speed to go."));
            setNextArgument(ArArg.ofDouble("stop distance", () -> myStopDistance, v -> myStopDistance = v,
                    "Distance at which to stop."));
        }

        /* Gets the sonar device from the robot, or deactivates this action if it is missing. */
        @Override
        public void setRobot(ArRobot robot) {
            super.setRobot(robot);
            mySonar = robot == null ? null : robot.findRangeDevice("sonar");
            if (robot == null) {
                ArLog.log(ArLog.Terse, "actionExample: ActionGo: Warning: I found no sonar, deactivating.");
                deactivate();
            }
        }

        /* Sets our desired forward velocity from the sonar's closest reading ahead. */
        @Override
        public ArActionDesired fire(ArActionDesired current) {
            double range;
            double speed;

            myDesired.reset();
            if (mySonar == null) {
                deactivate();
                return null;
            }
            range = mySonar.currentReadingPolar(-70, 70) - myRobot.getRobotRadius();
            if (range > myStopDistance) {
                speed = range * .3;
                if (speed > myMaxSpeed) {
                    speed = myMaxSpeed;
                }
                myDesired.setVel(speed);
            } else {
                myDesired.setVel(0);
            }
            return myDesired;
        }
    }

    /** Action that turns the robot away from obstacles detected by the sonar. */
    static final class ActionTurn extends ArAction {
        private ArRangeDevice mySonar;
        private final ArActionDesired myDesired = new ArActionDesired();
        private double myTurnThreshold;
        private double myTurnAmount;
        private int myTurning; // -1 == left, 1 == right, 0 == none

        ActionTurn(double turnThreshold, double turnAmount) {
            super("Turn");
            myTurnThreshold = turnThreshold;
            myTurnAmount = turnAmount;
            setNextArgument(ArArg.ofDouble("turn threshold (mm)", () -> myTurnThreshold, v -> myTurnThreshold = v,
                    "The number of mm away from obstacle to begin turnning."));
            setNextArgument(ArArg.ofDouble("turn amount (deg)", () -> myTurnAmount, v -> myTurnAmount = v,
                    "The number of degress to turn if turning."));
            myTurning = 0;
        }

        @Override
        public void setRobot(ArRobot robot) {
            super.setRobot(robot);
            mySonar = robot == null ? null : robot.findRangeDevice("sonar");
            if (mySonar == null) {
                ArLog.log(ArLog.Terse, "actionExample: ActionTurn: Warning: I found no sonar, deactivating.");
                deactivate();
            }
        }

        @Override
        public ArActionDesired fire(ArActionDesired currentDesired) {
            double leftRange;
            double rightRange;

            myDesired.reset();
            if (mySonar == null) {
                deactivate();
                return null;
            }
            leftRange = mySonar.currentReadingPolar(0, 100) - myRobot.getRobotRadius();
            rightRange = mySonar.currentReadingPolar(-100, 0) - myRobot.getRobotRadius();
            if (leftRange > myTurnThreshold && rightRange > myTurnThreshold) {
                myTurning = 0;
                myDesired.setDeltaHeading(0);
            } else if (myTurning != 0) {
                myDesired.setDeltaHeading(myTurnAmount * myTurning);
            } else if (leftRange < rightRange) {
                myTurning = -1;
                myDesired.setDeltaHeading(myTurnAmount * myTurning);
            } else {
                myTurning = 1;
                myDesired.setDeltaHeading(myTurnAmount * myTurning);
            }
            return myDesired;
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
        ArSonarDevice sonar = new ArSonarDevice();

        ArRobotConnector robotConnector = new ArRobotConnector(parser, robot);
        if (!robotConnector.connectRobot()) {
            ArLog.log(ArLog.Terse, "actionExample: Could not connect to the robot.");
            if (parser.checkHelpAndWarnUnparsed()) {
                Aria.logOptions();
                Aria.exit(1);
            }
        }
        if (!Aria.parseArgs() || !parser.checkHelpAndWarnUnparsed()) {
            Aria.logOptions();
            Aria.exit(1);
        }

        ArLog.log(ArLog.Normal, "actionExample: Connected to robot.");

        // Create instances of the actions defined above, plus ArActionStallRecover,
        // a predefined action from Aria.
        ActionGo go = new ActionGo(500, 350);
        ActionTurn turn = new ActionTurn(400, 10);
        ArActionStallRecover recover = new ArActionStallRecover();

        // Add the range device to the robot. You should add all the range
        // devices before you add actions
        robot.addRangeDevice(sonar);

        // Add our actions in order. The second argument is the priority,
        // with higher priority actions going first, and possibly pre-empting lower
        // priority actions.
        robot.addAction(recover, 100);
        robot.addAction(go, 50);
        robot.addAction(turn, 49);

        // Enable the motors
        robot.enableMotors();

        // Run the robot processing cycle.
        // 'true' means to return if it loses connection,
        // after which we exit the program.
        robot.run(true);

        Aria.exit(0);
    }
}
