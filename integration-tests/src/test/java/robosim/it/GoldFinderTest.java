package robosim.it;

import robosim.cli.Main;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Polygon;
import robosim.comms.CommsSettings;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.World;
import robosim.env.world.maze.MazeWorldWriter;
import robosim.env.world.xml.WorldReader;
import robosim.examples.goldfinder.Gold;
import robosim.examples.goldfinder.GoldFinder;
import robosim.geometry.BodyShape;
import robosim.geometry.GeometryClient;
import robosim.geometry.Pose2D;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.RobotParameters;

/** GoldFinder on generated 8×8 mazes: found, deterministic, and never an overlap. */
@Timeout(value = 5, unit = TimeUnit.MINUTES)
class GoldFinderTest {
    /** The step limit of every run: 25 minutes of simulated time. */
    static final long STEP_LIMIT = 15_000;
    static final int ROBOTS = 3;

    @TempDir
    Path dir;

    /** One run: its report and every snapshot a viewer saw. */
    record Run(RunReport report, WorldDescription world, List<Snapshot> snapshots) { }

    Run run(long seed) throws Exception {
        return run(seed, null);
    }

    /** One run, with messages travelling as {@code comms} says (null: the world's own way). */
    Run run(long seed, CommsSettings comms) throws Exception {
        Path file = dir.resolve("maze-" + seed + ".xml");
        int exit = Main.commandLine().execute("maze", "--cells", "8", "8", "--cell-size", "1500",
                "--seed", Long.toString(seed), "--robots", "8", "--out", file.toString());
        assertEquals(0, exit, "robosim maze wrote " + file);
        World world = WorldReader.read(file).withFirstRobots(ROBOTS);
        try (LocalEnvironment env = new LocalEnvironment(world, seed,
                ServerOptions.loopback().withMaxSteps(STEP_LIMIT).withWaitViewers(1))) {
            if (comms != null) {
                env.sim.setCommsSettings(comms);
            }
            SnapshotCollector viewer = new SnapshotCollector(env.viewerPort());
            List<Thread> team = GoldFinder.start("127.0.0.1", env.robotPort(), ROBOTS);
            RunReport r = env.await(180);
            for (Thread t : team) {
                t.join(10_000);
            }
            return new Run(r, viewer.world(), viewer.snapshots());
        }
    }

    @Test
    void theTeamFindsTheGoldInAtLeastNineOfTenMazesWithoutEverOverlapping() throws Exception {
        int found = 0;
        List<String> misses = new ArrayList<>();
        for (long seed = 1; seed <= 10; seed++) {
            Run run = run(seed);
            if (run.report().find() != null) {
                found++;
            } else {
                misses.add("seed " + seed + ": " + run.report().endReason());
            }
            assertNoOverlap(seed, run);
        }
        assertTrue(found >= 9, "found in " + found + " of 10 mazes within " + STEP_LIMIT + " steps; missed " + misses);
    }

    /** A Gold robot reads its maze's cell size from the world property the maze generator writes. */
    @Test
    void theRobotsReadTheCellSizeUnderTheNameTheMazeGeneratorWritesIt() {
        assertEquals(MazeWorldWriter.CELL_SIZE_PROPERTY, Gold.CELL_SIZE_PROPERTY);
    }

    @Test
    void aSeedGivesTheSameSearchEveryTime() throws Exception {
        Run a = run(4);
        Run b = run(4);
        assertNotNull(a.report().find());
        assertEquals(a.report().find(), b.report().find());
        assertEquals(a.report().robots(), b.report().robots());
        assertEquals(a.snapshots().size(), b.snapshots().size());
    }

    @Test
    void aSeedGivesTheSameSearchEveryTimeWithMessagesLostAndLate() throws Exception {
        CommsSettings lossy = new CommsSettings(0, false, 3, 0.25, 65536);
        Run a = run(4, lossy);
        Run b = run(4, lossy);
        assertNotNull(a.report().find(), "found with a quarter of the messages lost and the rest 3 steps late");
        assertEquals(a.report().find(), b.report().find());
        assertEquals(a.report().robots(), b.report().robots());
        assertEquals(poses(a), poses(b), "the same poses, step for step");
        assertNotEquals(poses(a), poses(run(4)), "losses change the run: the test compares runs that depend on them");
    }

    /** Every robot's true pose at every step, as text. */
    static List<String> poses(Run run) {
        List<String> out = new ArrayList<>();
        for (Snapshot s : run.snapshots()) {
            for (Snapshot.RobotView v : s.robots()) {
                out.add(s.step() + " " + v.name() + " " + v.x() + " " + v.y() + " " + v.th());
            }
        }
        return out;
    }

    /** Every step, from the true poses: no body inside a wall, no two bodies overlapping. */
    static void assertNoOverlap(long seed, Run run) {
        List<Polygon> walls = new ArrayList<>();
        for (WorldDescription.Obstacle o : run.world().obstacles()) {
            walls.add(GeometryClient.polygon(o.xy()));
        }
        GeometryClient geometry = new GeometryClient(walls);
        List<BodyShape> shapes = new ArrayList<>();
        for (WorldDescription.RobotInfo r : run.world().robots()) {
            RobotParameters p = r.parameters();
            shapes.add(BodyShape.rectangle(p.robotLengthFront(), p.robotLengthRear(), p.robotWidth()));
        }
        assertFalse(run.snapshots().isEmpty());
        org.locationtech.jts.geom.GeometryFactory f = new org.locationtech.jts.geom.GeometryFactory();
        for (Snapshot snapshot : run.snapshots()) {
            List<Polygon> bodies = new ArrayList<>();
            for (int i = 0; i < snapshot.robots().size(); i++) {
                Snapshot.RobotView v = snapshot.robots().get(i);
                Pose2D pose = new Pose2D(v.x(), v.y(), Math.toRadians(v.th()));
                String at = "seed " + seed + " step " + snapshot.step() + " robot " + v.name();
                assertFalse(geometry.overlaps(shapes.get(i), pose, -1), at + " overlaps a wall");
                bodies.add(f.createPolygon(shapes.get(i).ringAt(pose)));
            }
            for (int i = 0; i < bodies.size(); i++) {
                for (int j = i + 1; j < bodies.size(); j++) {
                    assertFalse(bodies.get(i).intersects(bodies.get(j)), "seed " + seed + " step " + snapshot.step()
                            + ": robots " + snapshot.robots().get(i).name() + " and " + snapshot.robots().get(j).name() + " overlap");
                }
            }
        }
    }
}
