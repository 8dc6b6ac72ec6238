package robosim.examples.aria;

import java.util.List;
import robosim.aria.ArActionGoto;
import robosim.aria.ArActionStop;
import robosim.aria.ArArgumentParser;
import robosim.aria.ArLog;
import robosim.aria.ArMap;
import robosim.aria.ArMapObject;
import robosim.aria.ArPose;
import robosim.aria.ArRobot;
import robosim.aria.ArRobotConnector;
import robosim.aria.ArUtil;
import robosim.aria.Aria;

/**
 * Planning on the map a robot runs in, written as an ARIA program (ARIA has no example of its own
 * for it; this one follows {@code gotoActionExample.cpp}'s shape): it reads the map given with
 * {@code -map FILE} through {@link ArMap}, lists its goals, docks, homes and forbidden lines and
 * areas, and drives to one goal ({@code -goal NAME}, else the map's first) with
 * {@link ArActionGoto}, through waypoints that keep {@value #CLEARANCE} mm clear of its walls and
 * points and of its forbidden lines and areas where the way allows ({@link MapRoute}).
 *
 * <p>Against a RoboSim Environment running the same map ({@code robosim env MAP.map}) the robot's
 * odometry is the map's frame, as it starts at the map's {@code RobotHome}; a robot whose odometry
 * starts at (0, 0, 0) (a Pioneer port, a real robot) is taken to start at the map's first
 * {@code RobotHome}, as a program without localization must assume ({@code ArRobot.moveTo}).
 */
public final class MapGoals {
    /**
     * How far the route keeps the robot's centre from the map's walls, points and forbidden lines
     * and areas where it can, mm: a Pioneer's radius and as much again.
     */
    static final double CLEARANCE = 500;
    /** How long the robot may take to reach the goal, ms, before the program gives up. */
    static final long TIMEOUT = 120_000;

    private MapGoals() {
    }

    /**
     * @param args {@code -map FILE [-goal NAME]}, then RoboSim's {@code NAME HOST PORT} or ARIA's
     *             robot arguments ({@code -help} lists them)
     */
    public static void main(String[] args) {
        Aria.init();
        ArArgumentParser parser = new ArArgumentParser(args);
        parser.loadDefaultArguments();
        String mapFile = parser.checkParameterArgument("-map");
        String goalName = parser.checkParameterArgument("-goal");
        ArRobot robot = new ArRobot();
        ArRobotConnector robotConnector = new ArRobotConnector(parser, robot);

        if (!robotConnector.connectRobot()) {
            ArLog.log(ArLog.Terse, "mapGoals: Could not connect to the robot.");
            if (parser.checkHelpAndWarnUnparsed()) {
                Aria.logOptions();
                Aria.exit(1);
            }
        }
        if (!Aria.parseArgs() || !parser.checkHelpAndWarnUnparsed() || mapFile == null) {
            ArLog.log(ArLog.Terse, "mapGoals: usage: -map <file.map> [-goal <name>] and the robot's arguments");
            Aria.logOptions();
            Aria.exit(1);
        }

        ArMap map = new ArMap("");
        if (!map.readFile(mapFile)) {
            ArLog.log(ArLog.Terse, "mapGoals: Could not read map file %s.", mapFile);
            Aria.exit(2);
        }
        ArLog.log(ArLog.Normal, "mapGoals: Map %s: %d lines, %d points, %d objects.", map.getFileName(),
                map.getNumLines(), map.getNumPoints(), map.getMapObjects().size());
        for (ArMapObject obj : map.getMapObjects()) {
            ArLog.log(ArLog.Normal, "mapGoals: Cairn: %s", obj);
        }

        ArMapObject goal = goalName != null ? map.findMapObject(goalName, "Goal", true)
                : map.findFirstMapObject(null, "Goal", true);
        if (goal == null) {
            ArLog.log(ArLog.Terse, "mapGoals: The map has no goal%s.", goalName != null ? " named " + goalName : "");
            Aria.exit(3);
        }

        robot.runAsync(true);
        robot.lock();
        ArMapObject home = map.findFirstMapObject(null, "RobotHome");
        if (home != null && robot.getPose().isEqual(new ArPose())) {
            ArLog.log(ArLog.Normal, "mapGoals: Odometry starts at (0, 0, 0): taking the robot to be at home '%s'.",
                    home.getName());
            robot.moveTo(home.getPose());
        }
        ArPose start = robot.getPose();
        robot.unlock();

        MapRoute planner = new MapRoute(map, CLEARANCE);
        List<ArPose> route = planner.plan(start, goal.getPose());
        if (route == null) {
            ArLog.log(ArLog.Terse, "mapGoals: No route to goal '%s' keeps off the map's walls and its %d forbidden segments.",
                    goal.getName(), planner.forbidden().size());
            Aria.exit(4);
        }
        ArLog.log(ArLog.Normal, "mapGoals: Going to goal '%s' at %.0f %.0f through %d waypoints.", goal.getName(),
                goal.getPose().getX(), goal.getPose().getY(), route.size() - 1);

        ArActionGoto gotoPoseAction = new ArActionGoto("goto");
        ArActionStop stopAction = new ArActionStop("stop");
        robot.lock();
        robot.addAction(gotoPoseAction, 50);
        robot.addAction(stopAction, 40);
        robot.enableMotors();
        robot.unlock();

        int next = 0;
        long waited = 0;
        boolean reached = false;
        while (Aria.getRunning() && robot.isRunning() && waited < TIMEOUT) {
            robot.lock();
            if (next == 0 || gotoPoseAction.haveAchievedGoal()) {
                if (next == route.size()) {
                    reached = true;
                    ArLog.log(ArLog.Normal, "mapGoals: Reached goal '%s': robot at %.0f %.0f.", goal.getName(),
                            robot.getX(), robot.getY());
                    robot.unlock();
                    break;
                }
                gotoPoseAction.setGoal(route.get(next++));
                ArLog.log(ArLog.Normal, "mapGoals: Going to %.0f %.0f", gotoPoseAction.getGoal().getX(),
                        gotoPoseAction.getGoal().getY());
            }
            robot.unlock();
            ArUtil.sleep(100);
            waited += 100;
        }
        if (!reached) {
            ArLog.log(ArLog.Terse, "mapGoals: Did not reach goal '%s' in %d seconds.", goal.getName(), TIMEOUT / 1000);
        }
        robot.lock();
        gotoPoseAction.cancelGoal();
        robot.unlock();
        robot.stopRunning();
        robot.waitForRunExit();
        Aria.exit(reached ? 0 : 5);
    }
}
