package robosim.examples.aria;

import robosim.aria.ArArgumentParser;
import robosim.aria.ArLog;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.ArTime;
import robosim.aria.ArUtil;
import robosim.aria.Aria;

/**
 * ARIA's {@code singleThreadLoopExample.cpp}, line for line: the program runs the robot's cycle
 * from its own loop ({@link ArRobot#loopOnce()}), with no thread of the robot's: it sets the robot
 * driving at 300 mm/s turning 10 deg/s, then each time round the loop runs one cycle, prints the
 * pose, velocity and battery, how long the loop took and how long it sleeps to make the loop about
 * 20 ms. Only for a platform without threads, as ARIA says.
 *
 * <p>Two differences, both so that it can be run and ended: the original gives the connector no
 * arguments (NULL), so it always connects to the simulator on localhost:8101; the port gives it the
 * command line, so that RoboSim's {@code NAME HOST PORT} or ARIA's {@code -rh HOST -rrtp PORT} send it
 * elsewhere (with none it connects as the original). And the original loops for ever; the port's loop
 * ends when the robot is disconnected (the run ended), where the original would go on printing the
 * last state it had.
 *
 * <p>In simulated time each loop takes 0 ms and sleeps 20 ms, which {@link ArUtil#sleep} makes one
 * step: a cycle a step, each with the step's new state. Against a robot server in real time the
 * original loops every 20 ms, five times a 100 ms cycle, and its pose changes every fifth loop.
 */
public final class SingleThreadLoopExample {
    private SingleThreadLoopExample() {
    }

    /**
     * @param args RoboSim's {@code NAME HOST PORT}, or ARIA's robot arguments; none: localhost:8101
     */
    public static void main(String[] args) {
        Aria.init();
        ArRobot robot = new ArRobot();

        // Connect to the robot, get some initial data from it such as type and name,
        // and then load parameter files for this robot.
        ArRobotConnector robotConnector = new ArRobotConnector(new ArArgumentParser(args), robot);
        if (!robotConnector.connectRobot()) {
            ArLog.log(ArLog.Terse, "singleThreadExample: Could not connect to the robot.");
            Aria.exit(1);
            return;
        }

        ArLog.log(ArLog.Normal, "singleThreadExample: Connected to robot.");

        robot.enableMotors();

        robot.setVel(300);
        robot.setRotVel(10);

        while (robot.isConnected()) {
            ArTime t = new ArTime();
            // Run one iteration of the ArRobot loop
            robot.loopOnce();

            // Print out some data from the SIP.
            final boolean soc = robot.hasStateOfCharge();
            double battv = 0.0;
            if (soc) {
                battv = robot.getStateOfCharge();
            } else {
                battv = robot.getBatteryVoltage();
            }
            ArLog.log(ArLog.Normal, "singleThreadExample: Pose=(%.2f,%.2f,%.2f), Trans.  Vel=%.2f, Battery=%.2f%c",
                    robot.getX(), robot.getY(), robot.getTh(), robot.getVel(), battv, soc ? '%' : 'V');

            // slow the loop down a little bit.
            long sleepTime = 20;
            if (t.mSecSince() > 20) {
                sleepTime = 0;
            } else {
                sleepTime -= t.mSecSince();
            }
            ArLog.log(ArLog.Normal, "singleThreadExample: loop took %d ms, sleeping %d ms", t.mSecSince(), sleepTime);

            if (t.mSecSince() > 100) {
                ArLog.log(ArLog.Normal, "singleThreadExample: warning: loop took longer than 100ms");
            }

            ArUtil.sleep(sleepTime);
        }

        Aria.exit(0);
    }
}
