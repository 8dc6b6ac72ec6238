package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.examples.aria.Lasers;
import robosim.examples.aria.TeleopActionsExample;
import robosim.examples.aria.TriangleDriveToActionExample;
import robosim.it.AriaExamplesTest.Ran;

/**
 * AriaCoda's laser and teleoperation examples ported to Java ({@code examples/aria}):
 * {@code teleopActionsExample.cpp}, {@code triangleDriveToActionExample.cpp} and {@code lasers.cpp},
 * each run as its ARIA program against an Environment in lockstep, its keys on standard input
 * (all pressed at the robot's first cycle).
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class AriaLaserExamplesTest {
    private static final String UP = "\u001b[A";
    private static final String LEFT = "\u001b[D";

    @TempDir
    Path dir;

    private static String port(ThreadedRun run) {
        return String.valueOf(run.port());
    }

    @Test
    void teleopActionsDrivesAsTheKeysSayAndTheLimitersStopItShortOfTheWall() throws Exception {
        // r1 faces the wall whose inner face is at x = 5900, 4.9 m ahead of its centre
        Path world = ThreadedRun.world(dir, "corridor.xml", """
                <world name="corridor" width="6000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="1000" y="3000" th="0" params="%ROBOTS%/p3dx.p"/>
                </world>
                """);
        try (ThreadedRun run = new ThreadedRun(world, 1, 300)) {
            // twelve presses of up: 12 × 25 = 300 mm/s; two of left: 2 × 8 = 16° to turn, for one cycle
            Future<Ran> r1 = run.robot(() -> AriaExamplesTest.runWithKeys(UP.repeat(12) + LEFT.repeat(2),
                    TeleopActionsExample::main, "r1", "127.0.0.1", port(run)));
            RunReport report = run.await();
            Ran ran = r1.get(60, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(ran.out().contains("teleopActionsExample: Connected."), ran.out());
            RobotSummary r = report.robots().get(0);
            // the left presses make one cycle's turn (ARIA's keydrive turns by the presses of the
            // cycle, then holds the heading): a few degrees, so it drifts left of its line
            assertTrue(r.th() >= 0 && r.th() <= 4, "heading: " + r);
            assertTrue(r.y() > 3040 && r.y() < 3120, "drifted left: " + r);
            // the near limiter stops it with 300 mm between its front (255.5 mm from its centre)
            // and the wall; nothing touched
            assertEquals(300, 5900 - (r.x() + 255.5), 10, "clearance: " + r);
            assertEquals(0, r.collisions(), "collisions: " + r);
            assertTrue(r.distance() > 4300, "driven by the up presses: " + r);
        }
    }

    @Test
    void triangleDriveToEndsFacingTheTrianglesVertexAtItsFinalDistance() throws Exception {
        Path world = LocalEnvironment.root().resolve("testLoadFiles/environment/triangle-target.xml");
        try (ThreadedRun run = new ThreadedRun(world, 1, 400)) {
            Future<Ran> r1 = run.robot(() -> AriaExamplesTest.runWithKeys("g", TriangleDriveToActionExample::main,
                    "r1", "127.0.0.1", port(run), "-connectLaser"));
            RunReport report = run.await();
            Ran ran = r1.get(60, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            assertTrue(ran.out().contains("triangleDriveToActionExample: Connected to robot.\nConnected to laser.\n"),
                    ran.out());
            RobotSummary r = report.robots().get(0);
            // the vertex is at (3500, 3000), the target facing 160°: the final point is 400 mm out
            // along that, facing back at the vertex (-20°). ARIA aligns to within a degree
            double finalX = 3500 + 400 * Math.cos(Math.toRadians(160));
            double finalY = 3000 + 400 * Math.sin(Math.toRadians(160));
            assertEquals(0, r.collisions(), "collisions: " + r);
            assertEquals(0, Math.hypot(r.x() - finalX, r.y() - finalY), 10, "at the final point: " + r);
            assertEquals(-20, r.th(), 1.5, "facing the vertex: " + r);
        }
    }

    @Test
    void lasersPrintsLaserOnesReadingsAsTheRoomsWallsAre() throws Exception {
        PioneerRun.room(dir);
        try (ThreadedRun run = new ThreadedRun(dir.resolve("room.xml"), 1, 120)) {
            Future<Ran> r1 = run.robot(() -> AriaExamplesTest.run(Lasers::main, "r1", "127.0.0.1", port(run),
                    "-connectLaser"));
            run.await();
            Ran ran = r1.get(60, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            // r1 at (3000, 3000) faces +x; the boundary's inner faces are at 100 and 9900; the laser
            // is 18 mm ahead. Of its 181 beams (-90° to 90°, one a degree) 152 meet a wall within its
            // 8 m. The nearest is the wall on the right, 2900 mm from the laser at -90°: (3018, 100),
            // 2900.06 mm from the centre at -89.6°, which polar readings are measured from
            String reading = "lasersExample: Laser #1 (lms2xx_1): connected.\n\tHave 152 'current' readings.\n\tHave 181"
                    + " 'raw' readings.\n\tClosest reading is at -90 degrees and is 2.9001 meters away.\n";
            assertTrue(ran.out().contains("lasersExample: Robot parameters include information for 1 lasers:\n"
                    + "\tlaser #1: pose=(x:18, y:0, z:0, th:0.00), powerOutput=\n"), ran.out());
            // the connector's settings as ARIA logs them, none given on the command line
            assertTrue(ran.out().contains("ArLaserConnector: laser #1: lms2xx_1: will connect to this laser, port=(null),"
                    + " portType=(null), remoteTCPPort=0, flipped=0, fov=(inf, -inf), increment=-inf.\n"
                    + "ArLaserConnector: command-line arguments have been parsed.\n"), ran.out());
            assertEquals(4, ran.out().split(java.util.regex.Pattern.quote(reading), -1).length - 1,
                    "every 3 s of 12: " + ran.out());
            assertTrue(ran.out().endsWith("lasersExample: exiting.\n"), ran.out());
        }
    }

    @Test
    void lasersWithNoLaserEnabledConnectsNoneAsAriaDoesForAPioneer() throws Exception {
        PioneerRun.room(dir);
        try (ThreadedRun run = new ThreadedRun(dir.resolve("room.xml"), 1, 40)) {
            Future<Ran> r1 = run.robot(() -> AriaExamplesTest.run(Lasers::main, "r1", "127.0.0.1", port(run)));
            run.await();
            Ran ran = r1.get(60, TimeUnit.SECONDS);
            assertEquals(0, ran.exit(), ran.out());
            // a Pioneer's LaserAutoConnect is false: without -connectLaser there is no laser to read
            assertTrue(ran.out().contains("lasersExample: Robot parameters include information for 0 lasers:\n"),
                    ran.out());
            assertTrue(ran.out().contains("ArLaserConnector: laser #1: lms2xx_1: will NOT connect to this laser,"),
                    ran.out());
            assertTrue(ran.out().contains("lasersExample: ArRobot provided a set of 0 ArLaser objects.\n"
                    + "lasersExample: No lasers.\n"), ran.out());
        }
    }

    @Test
    void lasersRefusesASecondLaserWithTheReasonAndExitsAsAriaDoesOnABadArgument() throws Exception {
        PioneerRun.room(dir);
        try (ThreadedRun run = new ThreadedRun(dir.resolve("room.xml"), 1, 40)) {
            Future<Ran> r1 = run.robot(() -> AriaExamplesTest.run(Lasers::main, "r1", "127.0.0.1", port(run),
                    "-connectLaser", "-laserType2", "lms2xx", "-connectLaser2"));
            Ran ran = r1.get(60, TimeUnit.SECONDS);
            run.await();
            // Aria.parseArgs fails at the laser RoboSim cannot make: the options, and exit code 2
            assertEquals(2, ran.exit(), ran.out());
            assertTrue(ran.out().contains("ArLaserConnector: laser 2: RoboSim simulates one laser per robot, laser 1"),
                    ran.out());
            assertTrue(ran.out().contains("Options for ArLaserConnector:"), ran.out());
        }
    }
}
