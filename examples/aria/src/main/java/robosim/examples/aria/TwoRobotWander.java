package robosim.examples.aria;

import robosim.aria.ArActionAvoidFront;
import robosim.aria.ArActionBumpers;
import robosim.aria.ArActionConstantVelocity;
import robosim.aria.ArActionStallRecover;
import robosim.aria.ArArgumentParser;
import robosim.aria.ArCommands;
import robosim.aria.ArLog;
import robosim.aria.ArRobot;
import robosim.aria.ArSonarDevice;
import robosim.aria.ArTcpConnection;
import robosim.aria.ArUtil;
import robosim.aria.Aria;

/**
 * ARIA's {@code twoRobotWander.cpp}, line for line: one program drives two robots, each through a
 * TCP connection of its own to a Pioneer robot server (RoboSim's Pioneer ports, MobileSim), both
 * wandering by ARIA's actions; every 10 seconds one stops and the other goes on.
 */
public final class TwoRobotWander {
    private TwoRobotWander() {
    }

    /**
     * @param args {@code [-rh1 HOST1] [-rh2 HOST2] [-rp1 PORT1] [-rp2 PORT2]}: the robots' Pioneer
     *             robot servers (default localhost, 8101 and 8102)
     */
    public static void main(String[] args) {
        Aria.init();
        ArArgumentParser argParser = new ArArgumentParser(args);
        String host1 = argParser.checkParameterArgument("-rh1");
        if (host1 == null) {
            host1 = "localhost";
        }
        String host2 = argParser.checkParameterArgument("-rh2");
        if (host2 == null) {
            host2 = "localhost";
        }

        int[] port1 = {8101};
        int[] port2 = {8101};
        if (host1.equals(host2)) {
            port2[0]++;
        }

        boolean[] argSet = {false};
        argParser.checkParameterArgumentInteger("-rp1", port1, argSet, false);
        if (!argSet[0]) {
            argParser.checkParameterArgumentInteger("-rrtp1", port1);
        }
        argSet[0] = false;
        argParser.checkParameterArgumentInteger("-rp2", port2, argSet, false);
        if (!argSet[0]) {
            argParser.checkParameterArgumentInteger("-rrtp2", port2);
        }

        if (!argParser.checkHelpAndWarnUnparsed()) {
            ArLog.log(ArLog.Terse, "Usage: twoRobotWander [-rh1 <hostname1>] [-rh2 <hostname2>] [-rp1 <port1>]"
                    + " [-rp2 <port2>]\n"
                    + "\t<hostname1> Is the network host name of the first robot. Default is localhost (for the"
                    + " simulator).\n"
                    + "\t<hostname2> Is the network host name of the second robot. Default is localhost (for the"
                    + " simulator).\n"
                    + "\t<port1> Is the TCP port number of the first robot. Default is 8101.\n"
                    + "\t<port2> Is the TCP port number of the second robot. Default is 8102 if both robots have the"
                    + " same hostname, or 8101 if they differ.\n\n");
            return;
        }

        // first robot:
        ArTcpConnection con1 = new ArTcpConnection();
        ArRobot robot1 = new ArRobot();
        ArSonarDevice sonar1 = new ArSonarDevice();
        ArActionStallRecover recover1 = new ArActionStallRecover();
        ArActionBumpers bumpers1 = new ArActionBumpers();
        ArActionAvoidFront avoidFront1 = new ArActionAvoidFront();
        ArActionConstantVelocity constantVelocity1 = new ArActionConstantVelocity("Constant Velocity", 400);

        // second robot:
        ArTcpConnection con2 = new ArTcpConnection();
        ArRobot robot2 = new ArRobot();
        ArSonarDevice sonar2 = new ArSonarDevice();
        ArActionStallRecover recover2 = new ArActionStallRecover();
        ArActionBumpers bumpers2 = new ArActionBumpers();
        ArActionAvoidFront avoidFront2 = new ArActionAvoidFront();
        ArActionConstantVelocity constantVelocity2 = new ArActionConstantVelocity("Constant Velocity", 400);

        int ret;
        String str;

        // open first connection
        ArLog.log(ArLog.Normal, "Connecting to first robot at %s:%d...", host1, port1[0]);
        if ((ret = con1.open(host1, port1[0])) != 0) {
            str = con1.getOpenMessage(ret);
            System.out.printf("Open failed to robot 1: %s%n", str);
            Aria.exit(1);
            return;
        }

        // set up first robot
        robot1.addRangeDevice(sonar1);
        robot1.setDeviceConnection(con1);
        if (!robot1.blockingConnect()) {
            System.out.printf("Could not connect to robot 1... exiting%n");
            Aria.exit(1);
            return;
        }

        robot1.comInt(ArCommands.ENABLE, 1);
        robot1.comInt(ArCommands.SOUNDTOG, 0);

        robot1.addAction(recover1, 100);
        robot1.addAction(bumpers1, 75);
        robot1.addAction(avoidFront1, 50);
        robot1.addAction(constantVelocity1, 25);

        // open second connection
        ArLog.log(ArLog.Normal, "Connecting to second robot at %s:%d...", host2, port2[0]);
        if ((ret = con2.open(host2, port2[0])) != 0) {
            str = con2.getOpenMessage(ret);
            System.out.printf("Open failed to robot 2: %s%n", str);
            Aria.exit(1);
            return;
        }

        // set up second robot
        robot2.addRangeDevice(sonar2);
        robot2.setDeviceConnection(con2);
        if (!robot2.blockingConnect()) {
            System.out.printf("Could not connect to robot 2... exiting%n");
            Aria.exit(1);
            return;
        }

        robot2.comInt(ArCommands.ENABLE, 1);
        robot2.comInt(ArCommands.SOUNDTOG, 0);

        robot2.addAction(recover2, 100);
        robot2.addAction(bumpers2, 75);
        robot2.addAction(avoidFront2, 50);
        robot2.addAction(constantVelocity2, 25);

        // start both robots
        robot1.runAsync(true);
        robot2.runAsync(true);

        // Switch between the robots every 10 seconds: stop one, and let the other's actions drive it.
        int curRobot = 1;
        while (robot1.isRunning() && robot2.isRunning()) {
            ArUtil.sleep(10000);
            robot1.lock();
            robot2.lock();
            if (curRobot == 1) {
                ArLog.log(ArLog.Normal, "Switching to robot 2.");
                robot1.stop();
                robot2.clearDirectMotion();
                curRobot = 2;
            } else {
                ArLog.log(ArLog.Normal, "Switching to robot 1.");
                robot2.stop();
                robot1.clearDirectMotion();
                curRobot = 1;
            }
            robot2.unlock();
            robot1.unlock();
        }

        ArLog.log(ArLog.Normal, "Both robots disconnected.");
        Aria.exit(0);
    }
}
