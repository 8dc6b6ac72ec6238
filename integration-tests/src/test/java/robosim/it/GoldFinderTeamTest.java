package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.cli.Background;
import robosim.env.net.ServerOptions;
import robosim.env.world.xml.WorldReader;
import robosim.examples.goldfinder.Gold;
import robosim.examples.goldfinder.GoldFinder;
import robosim.protocol.Snapshot;

/**
 * How a team of Gold robots divides a maze, watched from the robots' true poses and drawings: at a
 * junction with two open branches two robots take different branches, and a cell claimed by a
 * teammate that then fails is explored all the same.
 *
 * <p>The T world has 1.5 m cells and no gold: r2 and r1, one behind the other, in a stem (3, 0)
 * and (3, 1) below the junction (3, 2), whose arms run west and east along the top row. From the
 * stem r1 reads the junction's open sides with its laser: two frontiers, two cells from r1 and
 * three from r2. What r1 tells (its claim, then the cell it drives into) keeps r2 off its branch;
 * {@code TeamPlanTest} checks the claims alone.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class GoldFinderTeamTest {
    static final String T_WORLD = """
            <world name="t-junction" width="10500" height="4500" stepMs="100" boundary="true">
              <property name="cellSize" value="1500"/>
              <wall x1="0" y1="1500" x2="4500" y2="1500"/>
              <wall x1="6000" y1="1500" x2="10500" y2="1500"/>
              <wall x1="0" y1="3000" x2="4500" y2="3000"/>
              <wall x1="6000" y1="3000" x2="10500" y2="3000"/>
              <wall x1="4500" y1="0" x2="4500" y2="3000"/>
              <wall x1="6000" y1="0" x2="6000" y2="3000"/>
              <robot name="r1" type="pioneer" x="5250" y="2250" th="90" params="%ROBOTS%/p3dx.p"/>
              <robot name="r2" type="pioneer" x="5250" y="750" th="90" params="%ROBOTS%/p3dx.p"/>
            </world>
            """;

    @TempDir
    Path dir;

    /** Which arm each robot drove into first: "west", "east", or absent. */
    static Map<String, String> firstArms(List<Snapshot> snapshots) {
        Map<String, String> first = new LinkedHashMap<>();
        for (Snapshot s : snapshots) {
            for (Snapshot.RobotView v : s.robots()) {
                String bend = v.y() < 3000 ? null : v.x() < 4500 - 300 ? "west" : v.x() > 6000 + 300 ? "east" : null;
                if (bend != null) {
                    first.putIfAbsent(v.name(), bend);
                }
            }
        }
        return first;
    }

    @Test
    void twoRobotsAtAJunctionWithTwoOpenBranchesTakeDifferentBranches() throws Exception {
        Path world = ThreadedRun.world(dir, "t.xml", T_WORLD);
        for (long seed = 1; seed <= 3; seed++) {
            try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), seed,
                    ServerOptions.loopback().withMaxSteps(700).withWaitViewers(1))) {
                SnapshotCollector viewer = new SnapshotCollector(env.viewerPort());
                List<Thread> team = GoldFinder.start("127.0.0.1", env.robotPort(), 2);
                env.await(120);
                for (Thread t : team) {
                    t.join(10_000);
                }
                Map<String, String> first = firstArms(viewer.snapshots());
                assertEquals(2, first.size(), "seed " + seed + ": both robots drove into an arm within 700 steps: " + first);
                assertNotEquals(first.get("r1"), first.get("r2"), "seed " + seed + ": r1 and r2 took different branches");
            }
        }
    }

    /**
     * A loop of six cells: r1 stands in (1, 0) below the junction (1, 1) where r2 stands; the
     * corner (0, 0) beside r1 opens onto r1's cell and onto (0, 1), which opens onto the
     * junction; (2, 1), east of the junction, is a dead end. r2 explores the corner from (0, 1), by
     * reading it with its laser or by driving in.
     */
    static final String LOOP_WORLD = """
            <world name="loop" width="4500" height="3000" stepMs="100" boundary="true">
              <property name="cellSize" value="1500"/>
              <wall x1="3000" y1="0" x2="3000" y2="1500"/>
              <wall x1="3000" y1="1500" x2="4500" y2="1500"/>
              <robot name="r1" type="pioneer" x="2250" y="750" th="90" params="%ROBOTS%/p3dx.p"/>
              <robot name="r2" type="pioneer" x="2250" y="2250" th="90" params="%ROBOTS%/p3dx.p"/>
            </world>
            """;

    @Test
    void aCellClaimedByATeammateThatFailsIsExploredAllTheSame() throws Exception {
        Path world = ThreadedRun.world(dir, "loop.xml", LOOP_WORLD);
        try (LocalEnvironment env = new LocalEnvironment(WorldReader.read(world), 1,
                ServerOptions.loopback().withMaxSteps(1200).withWaitViewers(1))) {
            SnapshotCollector viewer = new SnapshotCollector(env.viewerPort());
            // r1 claims the corner beside it (one cell away, as near as r2 can ever be, and r1 goes
            // first), says it drives there, and fails while it turns
            Gold r1 = new Gold("r1", "127.0.0.1", env.robotPort());
            CountDownLatch atStep8 = new CountDownLatch(1);
            r1.addUserTask("test: step 8", 0, () -> {
                if (r1.getStep() >= 8) {
                    atStep8.countDown();
                }
            });
            Future<Void> program = Background.run("gold-r1", () -> {
                if (r1.blockingConnect()) {
                    r1.search();
                }
            });
            Gold r2 = new Gold("r2", "127.0.0.1", env.robotPort());
            Future<Void> survivor = Background.run("gold-r2", () -> {
                if (r2.blockingConnect()) {
                    r2.search();
                    r2.disconnect();
                }
            });
            assertTrue(atStep8.await(60, TimeUnit.SECONDS), "r1 reaches step 8");
            r1.disconnect();
            program.get(30, TimeUnit.SECONDS);
            env.await(120);
            survivor.get(30, TimeUnit.SECONDS);
            List<Snapshot> snapshots = viewer.snapshots();
            Snapshot.RobotView failed = snapshots.get(snapshots.size() - 1).robots().get(0);
            assertTrue(failed.x() > 1500, "r1 failed before it reached the corner: " + failed.x());
            // what r2 knows, as it draws it: a dot at the centre of every cell whose walls it knows
            double[] known = null;
            for (Snapshot s : snapshots) {
                for (Snapshot.Drawing d : s.drawings()) {
                    if (d.robot().equals("r2") && d.layer().equals("known")) {
                        known = d.figures().get(0).xy();
                    }
                }
            }
            assertNotNull(known, "r2 drew what it knows");
            boolean corner = false;
            for (int i = 0; i < known.length; i += 2) {
                corner |= known[i] < 1500 && known[i + 1] < 1500;
            }
            assertTrue(corner, "r2 explored the corner r1 had claimed, once r1's claim lapsed");
        }
    }
}
