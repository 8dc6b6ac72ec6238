package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArLineSegment;
import robosim.aria.ArPose;
import robosim.cli.Background;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.env.world.xml.WorldReader;
import robosim.examples.aria.MapGoals;
import robosim.it.AriaExamplesTest.Ran;
import robosim.protocol.Snapshot;

/**
 * ARIA's {@code ArMap} in a robot program: the MapGoals example reads the map its Environment runs,
 * lists its objects and drives to a goal round a forbidden line, keeping out of a forbidden area,
 * in lockstep and through a Pioneer port.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class AriaMapTest {
    /**
     * An 8 m by 6 m room. A forbidden line across the middle (x = 4000, y 1500 to 4500) stands
     * between the home and the goal; a forbidden area covers the way round its north end, so the
     * route goes round its south end; a wall (x = 5500, y 0 to 4000) then stands between it and
     * the goal, so the route goes north again, round the wall's end. AriaCoda's ArMap reads it the
     * same (it refuses {@code NumPoints: 0}, so the map has no point header).
     */
    static final String ROOM = """
            2D-Map
            LineMinPos: 0 0
            LineMaxPos: 8000 6000
            NumLines: 5
            Resolution: 20
            Cairn: RobotHome 1000 3000 0 "" ICON "start"
            Cairn: Goal 7000 3000 0.000000 "" ICON "east"
            Cairn: GoalWithHeading 1000 1000 90.000000 "" ICON "corner" "a goal with a heading"
            Cairn: Dock 500 5000 180 "" ICON "dock"
            Cairn: ForbiddenLine 0 0 0.000000 "" ICON "fence" 4000 1500 4000 4500
            Cairn: ForbiddenArea 0 0 0.000000 "" ICON "pit" 3300 4800 4700 5900
            LINES
            0 0 8000 0
            8000 0 8000 6000
            8000 6000 0 6000
            0 6000 0 0
            5500 0 5500 4000
            DATA
            """;

    @TempDir
    Path dir;

    @Test
    void mapGoalsListsTheMapsObjectsAndDrivesToTheGoalRoundTheForbiddenLine() throws Exception {
        Path map = Files.writeString(dir.resolve("room.map"), ROOM);
        try (ThreadedRun run = new ThreadedRun(map, 1, 2000)) {
            Future<Ran> r = run.robot(() -> AriaExamplesTest.run(MapGoals::main, "-map", map.toString(), "p3dx_1",
                    "127.0.0.1", String.valueOf(run.port())));
            Ran ran = r.get(150, TimeUnit.SECONDS);
            RunReport report = run.await();
            String out = ran.out();
            assertEquals(0, ran.exit(), out);
            assertTrue(out.contains("mapGoals: Map " + map + ": 5 lines, 0 points, 6 objects.\n"), out);
            assertTrue(out.contains("mapGoals: Cairn: Goal 7000 3000 0.000000 \"\" ICON \"east\"\n"), out);
            assertTrue(out.contains("mapGoals: Cairn: GoalWithHeading 1000 1000 90.000000 \"a goal with a heading\""
                    + " ICON \"corner\"\n"), out);
            assertTrue(out.contains("mapGoals: Cairn: ForbiddenLine 0 0 0.000000 \"\" ICON \"fence\" 4000 1500 4000"
                    + " 4500\n"), out);
            // south round the fence's end, north along the wall, round its end, and on to the goal
            assertTrue(out.contains("mapGoals: Going to goal 'east' at 7000 3000 through 8 waypoints.\n"
                    + "mapGoals: Going to 3750 1050\nmapGoals: Going to 4250 950\nmapGoals: Going to 4950 1750\n"
                    + "mapGoals: Going to 4950 4050\n"), out);
            assertTrue(out.contains("mapGoals: Going to 7000 3000\n"), out);


            // lockstep: the same run each time, 21.5 s of simulated time, about 7.4 m driven
            RobotSummary robot = report.robots().get(0);
            assertEquals(0, robot.collisions(), "collisions: " + robot);
            // lockstep: the same run each time, 39.4 s of simulated time, about 10.4 m driven
            assertEquals(6990.3, robot.x(), 1, "x: " + robot);
            assertEquals(3013.3, robot.y(), 1, "y: " + robot);
            assertEquals(10441, robot.distance(), 5, "distance: " + robot);
            assertEquals(394, report.steps(), 3, "steps: " + report.steps());

            List<ArPose> path = truePath(run);
            assertTrue(path.size() > 50, "steps seen: " + path.size());
            ArLineSegment fence = new ArLineSegment(4000, 1500, 4000, 4500);
            ArLineSegment wall = new ArLineSegment(5500, 0, 5500, 4000);
            double closest = Double.MAX_VALUE;
            double closestToWall = Double.MAX_VALUE;
            for (int i = 1; i < path.size(); i++) {
                ArLineSegment step = new ArLineSegment(path.get(i - 1), path.get(i));
                assertTrue(!step.intersects(fence), "the robot crossed the forbidden line at step " + i);
                assertTrue(!step.intersects(wall), "the robot went through the wall at step " + i);
                closest = Math.min(closest, path.get(i).findDistanceTo(new ArPose(4000, 1500)));
                double perp = wall.getPerpSquaredDist(path.get(i));
                closestToWall = Math.min(closestToWall, perp >= 0 ? Math.sqrt(perp)
                        : Math.min(wall.getEndPoint1().findDistanceTo(path.get(i)),
                        wall.getEndPoint2().findDistanceTo(path.get(i))));
                assertTrue(path.get(i).getY() < 4800, "the robot went into the forbidden area: " + path.get(i));
            }
            assertTrue(closestToWall > 450, "the robot passed " + closestToWall + " mm from the wall");
            // 600 mm planned; ArActionGoto cuts the corner as it turns for the next waypoint: 489 mm
            assertTrue(closest > 450, "the robot passed " + closest + " mm from the forbidden line's end");
        }
    }

    @Test
    void mapGoalsDrivesThroughTheShippedOfficesDoorToItsDesk() throws Exception {
        Path office = LocalEnvironment.root().resolve("testLoadFiles/environment/office.map");
        try (ThreadedRun run = new ThreadedRun(office, 1, 2000)) {
            Future<Ran> r = run.robot(() -> AriaExamplesTest.run(MapGoals::main, "-map", office.toString(), "-goal",
                    "desk", "p3dx_1", "127.0.0.1", String.valueOf(run.port())));
            Ran ran = r.get(150, TimeUnit.SECONDS);
            RunReport report = run.await();
            String out = ran.out();
            assertEquals(0, ran.exit(), out);
            // from the home in the west room, through the door in the wall at x = 6000 (y 5400 to
            // 6600), past the desk's points, to the goal
            assertTrue(out.contains("mapGoals: Map " + office + ": 8 lines, 164 points, 4 objects.\n"), out);
            assertTrue(out.contains("mapGoals: Going to 6050 6050\n"), out);
            assertTrue(out.contains("mapGoals: Reached goal 'desk'"), out);
            RobotSummary robot = report.robots().get(0);
            assertEquals(0, robot.collisions(), "collisions: " + robot);
            assertEquals(9500, robot.x(), 100, "x: " + robot);
            assertEquals(5500, robot.y(), 100, "y: " + robot);
        }
    }

    @Test
    void throughThePioneerPortTheOdometryStartsAtZeroAndIsTakenToBeAtTheMapsHome() throws Exception {
        Path map = Files.writeString(dir.resolve("room.map"), ROOM);
        try (PioneerRun run = new PioneerRun(WorldReader.read(map), false, code -> { })) {
            Ran ran = Background.supply("mapGoals", () -> AriaExamplesTest.run(MapGoals::main, "-map", map.toString(),
                    "-goal", "corner", "-remoteHost", "127.0.0.1", "-rrtp", String.valueOf(run.ports.portOf("p3dx_1"))))
                    .get(120, TimeUnit.SECONDS);
            String out = ran.out();
            assertEquals(0, ran.exit(), out);
            assertTrue(out.contains("mapGoals: Odometry starts at (0, 0, 0): taking the robot to be at home 'start'.\n"
                    + "mapGoals: Going to goal 'corner' at 1000 1000 through 0 waypoints.\nmapGoals: Going to 1000 1000\n"),
                    out);
            Matcher at = Pattern.compile("mapGoals: Reached goal 'corner': robot at (-?\\d+) (-?\\d+)\\.").matcher(out);
            assertTrue(at.find(), out);
            // the Pioneer port runs in real time, so not to the millimetre of a lockstep run; the
            // goal, the map's GoalWithHeading, is found as a Goal, as ARIA's findMapObject does
            assertEquals(1000, Integer.parseInt(at.group(1)), 100, out);
            assertEquals(1000, Integer.parseInt(at.group(2)), 100, out);
        }
    }

    @Test
    void mapGoalsGivesUpOnABadMapNamingTheFileAndLine() throws Exception {
        Path map = Files.writeString(dir.resolve("room.map"), ROOM);
        Path bad = Files.writeString(dir.resolve("bad.map"), "2D-Map\nCairn: Goal 1 2\n");
        try (ThreadedRun run = new ThreadedRun(map, 1, 300)) {
            Future<Ran> r = run.robot(() -> AriaExamplesTest.run(MapGoals::main, "-map", bad.toString(), "p3dx_1",
                    "127.0.0.1", String.valueOf(run.port())));
            Ran ran = r.get(60, TimeUnit.SECONDS);
            assertEquals(2, ran.exit(), ran.out());
            assertTrue(ran.out().contains("ArMap::readFile: " + bad + ":2: a Cairn has 3 values but needs at least 7"),
                    ran.out());
            assertTrue(ran.out().contains("mapGoals: Could not read map file " + bad + ".\n"), ran.out());
        }
    }

    private static List<ArPose> truePath(ThreadedRun run) {
        List<ArPose> path = new ArrayList<>();
        synchronized (run.snapshots) {
            for (Snapshot s : run.snapshots) {
                if (!s.robots().isEmpty()) {
                    Snapshot.RobotView v = s.robots().get(0);
                    path.add(new ArPose(v.x(), v.y()));
                }
            }
        }
        return path;
    }
}
