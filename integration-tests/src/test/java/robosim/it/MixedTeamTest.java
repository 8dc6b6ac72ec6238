package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.examples.scoutwander.ScoutWander;
import robosim.examples.wander.Wander;
import robosim.protocol.Snapshot;

/** The shipped mixed team, one Scout and two Pioneers, over TCP: deterministic per seed. */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class MixedTeamTest {
    static final Path WORLD = LocalEnvironment.root().resolve("testLoadFiles/environment/mixed-team.xml");
    static final int STEPS = 300;

    @TempDir
    Path dir;

    /** One run: the report and every robot's true pose at every step. */
    record Run(RunReport report, List<String> trajectory) { }

    private static Run run(long seed) throws Exception {
        try (ThreadedRun run = new ThreadedRun(WORLD, seed, STEPS)) {
            String port = Integer.toString(run.port());
            List<Future<Object>> programs = new ArrayList<>();
            programs.add(run.robot(() -> {
                ScoutWander.main(new String[] {"s1", "127.0.0.1", port});
                return null;
            }));
            for (String pioneer : List.of("r1", "r2")) {
                programs.add(run.robot(() -> {
                    Wander.main(new String[] {pioneer, "127.0.0.1", port});
                    return null;
                }));
            }
            RunReport report = run.await();
            for (Future<Object> p : programs) {
                p.get(30, TimeUnit.SECONDS);
            }
            List<String> trajectory = new ArrayList<>();
            synchronized (run.snapshots) {
                for (Snapshot f : run.snapshots) {
                    for (Snapshot.RobotView v : f.robots()) {
                        trajectory.add(f.step() + " " + v.name() + " " + v.x() + " " + v.y() + " " + v.th());
                    }
                }
            }
            return new Run(report, trajectory);
        }
    }

    @Test
    void theShippedWorldHasAScoutAndTwoPioneers() throws Exception {
        World world = WorldReader.read(WORLD);
        assertEquals(List.of("s1", "r1", "r2"), world.robots().stream().map(r -> r.name()).toList());
        assertEquals(List.of("scout", "pioneer", "pioneer"), world.robots().stream().map(r -> r.type()).toList());
    }

    @Test
    void aSeedGivesTheSameMixedRunEveryTime() throws Exception {
        Run a = run(11);
        Run b = run(11);
        assertEquals(STEPS, a.report().steps());
        assertEquals(a.report().robots(), b.report().robots(), "the same final poses");
        assertEquals(a.trajectory(), b.trajectory(), "the same poses at every step");
        for (RobotSummary r : a.report().robots()) {
            assertTrue(r.distance() > 1000, r.name() + " wandered: " + r);
        }
    }

    @Test
    void theScoutWanderRunsInAJvmOfItsOwnBesideThePioneers() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("mixed-team.xml", ServerOptions.loopback().withMaxSteps(100))) {
            Path log = dir.resolve("s1.log");
            h.robotJvm("robosim.examples.scoutwander.ScoutWander", "s1", log);
            h.robotJvm("robosim.examples.wander.Wander", "r1", dir.resolve("r1.log"));
            h.robotJvm("robosim.examples.wander.Wander", "r2", dir.resolve("r2.log"));
            RunReport r = h.await();
            assertEquals(100, r.steps(), r.endReason());
            RobotSummary scout = r.robots().get(0);
            assertEquals("s1", scout.name());
            assertTrue(scout.distance() > 500, "the Scout wandered: " + scout + "\n" + Files.readString(log));
        }
    }
}
