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
     * route goes round its south end, 600 mm past it, at (4000, 900). AriaCoda's ArMap reads it
     * the same (it refuses {@code NumPoints: 0}, so the map has no point header).
     */
    static final String ROOM = """
            2D-Map
            LineMinPos: 0 0
            LineMaxPos: 8000 6000
            NumLines: 4
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
            assertTrue(out.contains("mapGoals: Map " + map + ": 4 lines, 0 points, 6 objects.\n"), out);
            assertTrue(out.contains("mapGoals: Cairn: Goal 7000 3000 0.000000 \"\" ICON \"east\"\n"), out);
            assertTrue(out.contains("mapGoals: Cairn: GoalWithHeading 1000 1000 90.000000 \"a goal with a heading\""
                    + " ICON \"corner\"\n"), out);
            assertTrue(out.contains("mapGoals: Cairn: ForbiddenLine 0 0 0.000000 \"\" ICON \"fence\" 4000 1500 4000"
                    + " 4500\n"), out);
            assertTrue(out.contains("mapGoals: Going to goal 'east' at 7000 3000 through 1 waypoints.\n"
                    + "mapGoals: Going to 4000 900\n"), out);
            assertTrue(out.contains("mapGoals: Going to 7000 3000\n"), out);

            assertTrue(out.contains("mapGoals: Reached goal 'east': robot at 6990 2992.\n"), out);

            // lockstep: the same run each time, 21.5 s of simulated time, about 7.4 m driven
            RobotSummary robot = report.robots().get(0);
            assertEquals(6989.5, robot.x(), 1, "x: " + robot);
            assertEquals(2992.3, robot.y(), 1, "y: " + robot);
            assertEquals(7360, robot.distance(), 5, "distance: " + robot);
            assertEquals(0, robot.collisions(), "collisions: " + robot);
            assertTrue(report.steps() >= 205 && report.steps() <= 225, "steps: " + report.steps());

            List<ArPose> path = truePath(run);
            assertTrue(path.size() > 50, "steps seen: " + path.size());
            ArLineSegment fence = new ArLineSegment(4000, 1500, 4000, 4500);
            double closest = Double.MAX_VALUE;
            for (int i = 1; i < path.size(); i++) {
                ArLineSegment step = new ArLineSegment(path.get(i - 1), path.get(i));
                assertTrue(!step.intersects(fence), "the robot crossed the forbidden line at step " + i);
                closest = Math.min(closest, path.get(i).findDistanceTo(new ArPose(4000, 1500)));
                assertTrue(path.get(i).getY() < 4800, "the robot went into the forbidden area: " + path.get(i));
            }
            // 600 mm planned; ArActionGoto cuts the corner as it turns for the next waypoint: 489 mm
            assertTrue(closest > 450, "the robot passed " + closest + " mm from the forbidden line's end");
        }
    }

    @Test
    void throughThePioneerPortTheOdometryStartsAtZeroAndIsTakenToBeAtTheMapsHome() throws Exception {
        Path map = Files.writeString(dir.resolve("room.map"), ROOM);
        try (PioneerRun run = new PioneerRun(WorldReader.read(map), false, code -> { })) {
            Ran ran = Background.supply("mapGoals", () -> AriaExamplesTest.run(MapGoals::main, "-map", map.toString(),
                    "-remoteHost", "127.0.0.1", "-rrtp", String.valueOf(run.ports.portOf("p3dx_1"))))
                    .get(120, TimeUnit.SECONDS);
            String out = ran.out();
            assertEquals(0, ran.exit(), out);
            assertTrue(out.contains("mapGoals: Odometry starts at (0, 0, 0): taking the robot to be at home 'start'.\n"
                    + "mapGoals: Going to goal 'east' at 7000 3000 through 1 waypoints.\nmapGoals: Going to 4000 900\n"),
                    out);
            Matcher at = Pattern.compile("mapGoals: Reached goal 'east': robot at (-?\\d+) (-?\\d+)\\.").matcher(out);
            assertTrue(at.find(), out);
            // the Pioneer port runs in real time, so not to the millimetre of the lockstep run
            assertEquals(7000, Integer.parseInt(at.group(1)), 100, out);
            assertEquals(3000, Integer.parseInt(at.group(2)), 100, out);
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
