package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.protocol.Snapshot;

/** An Environment and two robots, each in a JVM of its own, over TCP on loopback. */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class EndToEndTest {
    @TempDir
    Path dir;

    @Test
    void twoRobotsInTheirOwnJvmsDriveReadSonarAndEndInFreeSpace() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback())) {
            Process a = h.robotJvm(SonarDriver.class.getName(), "r1", dir.resolve("r1.log"));
            Process b = h.robotJvm(SonarDriver.class.getName(), "r2", dir.resolve("r2.log"));
            RunReport report = h.await();
            assertTrue(a.waitFor(30, TimeUnit.SECONDS) && b.waitFor(30, TimeUnit.SECONDS));
            assertEquals(0, a.exitValue(), Files.readString(dir.resolve("r1.log")));
            assertEquals(0, b.exitValue(), Files.readString(dir.resolve("r2.log")));
            assertEquals("every robot has disconnected", report.endReason());
            for (RobotSummary r : report.robots()) {
                assertEquals(600, r.distance(), 45, r.name() + " drove its move");
                assertFalse(h.sim.overlapsAnything(r.name()), r.name() + " ends in free space");
                assertEquals(0, r.collisions());
            }
            for (String name : List.of("r1", "r2")) {
                String log = Files.readString(dir.resolve(name + ".log"));
                assertTrue(log.contains("sonar before 5000"), "never-reported sonar reads 5000:\n" + log);
                int first = Integer.parseInt(log.replaceAll("(?s).*sonar first (\\d+).*", "$1"));
                assertTrue(first > 100 && first < 5000, "a real reading after the first step: " + first);
                int after = Integer.parseInt(log.replaceAll("(?s).*sonar after (\\d+).*", "$1"));
                assertTrue(after != first, "sonar changed after driving and turning:\n" + log);
            }
        }
    }

    @Test
    void theSameWorldAndProgramsTwiceGiveIdenticalTrajectories() throws Exception {
        List<Snapshot> first = wanderRun(dir.resolve("one"));
        List<Snapshot> second = wanderRun(dir.resolve("two"));
        assertEquals(151, first.size(), "snapshots 0 to 150");
        assertEquals(first.size(), second.size());
        boolean moved = false;
        for (int i = 0; i < first.size(); i++) {
            List<Snapshot.RobotView> x = first.get(i).robots();
            List<Snapshot.RobotView> y = second.get(i).robots();
            for (int k = 0; k < x.size(); k++) {
                String at = "step " + first.get(i).step() + " robot " + x.get(k).name();
                assertEquals(x.get(k).x(), y.get(k).x(), 0.0, at);
                assertEquals(x.get(k).y(), y.get(k).y(), 0.0, at);
                assertEquals(x.get(k).th(), y.get(k).th(), 0.0, at);
                moved |= x.get(k).x() != first.get(0).robots().get(k).x();
            }
        }
        assertTrue(moved, "the robots moved");
    }

    private List<Snapshot> wanderRun(Path logs) throws Exception {
        Files.createDirectories(logs);
        try (LocalEnvironment h = new LocalEnvironment("small-maze.xml", ServerOptions.loopback().withMaxSteps(150).withWaitViewers(1))) {
            SnapshotCollector viewer = new SnapshotCollector(h.viewerPort());
            h.robotJvm("robosim.examples.wander.Wander", "r1", logs.resolve("r1.log"));
            h.robotJvm("robosim.examples.wander.Wander", "r2", logs.resolve("r2.log"));
            h.await();
            return viewer.snapshots();
        }
    }
}
