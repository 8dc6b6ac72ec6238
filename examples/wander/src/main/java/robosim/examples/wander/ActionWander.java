package robosim.examples.wander;

import robosim.aria.ArActionAvoidFront;
import robosim.aria.ArActionBumpers;
import robosim.aria.ArActionConstantVelocity;
import robosim.aria.ArActionStallRecover;
import robosim.aria.ArRobot;
import robosim.aria.ArSonarDevice;

/**
 * A Pioneer that wanders built from ARIA's standard actions, as ARIA's {@code wander.cpp} is: stall
 * recovery above the bumpers, above avoiding what is near ahead (225 mm, turning in place), above
 * avoiding what is farther ahead (ARIA's defaults: 450 mm, slowing, turning 15°), above a constant
 * 400 mm/s. The resolver does the rest: each action gets the strength the higher ones leave.
 *
 * <p>Run it as {@code bin/robosim robot robosim.examples.wander.ActionWander NAME HOST PORT [PARAMFILE]}.
 */
public final class ActionWander {
    private ActionWander() {
    }

    /**
     * Adds the wander actions and the sonar as a range device to a robot, with wander.cpp's priorities.
     *
     * @param robot the robot
     */
    public static void addTo(ArRobot robot) {
        robot.addRangeDevice(new ArSonarDevice());
        robot.addAction(new ArActionStallRecover(), 100);
        robot.addAction(new ArActionBumpers(), 75);
        robot.addAction(new ArActionAvoidFront("Avoid Front Near", 225, 0, 15), 50);
        robot.addAction(new ArActionAvoidFront(), 49);
        robot.addAction(new ArActionConstantVelocity("Constant Velocity", 400), 25);
    }

    /**
     * Connects, enables the motors, adds the actions and lets them drive until the run ends.
     *
     * @param args NAME HOST PORT [PARAMFILE]
     */
    public static void main(String[] args) {
        if (args.length < 3) {
            throw new IllegalArgumentException("usage: ActionWander NAME HOST PORT [PARAMFILE]");
        }
        ArRobot robot = new ArRobot(args[0], args[1], Integer.parseInt(args[2]), args.length > 3 ? args[3] : "p3dx");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("robot " + args[0] + " could not connect: " + robot.getConnectionError());
        }
        robot.enableMotors();
        addTo(robot);
        robot.run();
    }
}
