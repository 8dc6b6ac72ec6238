package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.aria.ArRobot;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.examples.wallfollower.WallFollower;
import robosim.protocol.Snapshot;

/** The laser wall-follower ({@code examples/wall-follower}) goes round a 6 m room along its walls. */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class WallFollowerExampleTest {
    private static final int STEPS = 500;
    private static final double ROOM = 6000;

    @TempDir
    Path dir;

    @Test
    void itFindsAWallThenKeepsNearTheWallsWithoutTouchingThem() throws Exception {
        Path world = ThreadedRun.world(dir, "room.xml", """
                <?xml version="1.0" encoding="UTF-8"?>
                <world name="room" width="6000" height="6000" stepMs="100" boundary="true">
                  <robot name="r1" type="pioneer" x="3000" y="2500" th="0" params="%ROBOTS%/p3dx.p"/>
                </world>
                """);
        try (ThreadedRun run = new ThreadedRun(world, 1, STEPS)) {
            run.robot(() -> {
                WallFollower follower = new WallFollower(new ArRobot("r1", "127.0.0.1", run.port(), "p3dx"));
                follower.connect();
                follower.run();
                return null;
            });
            RunReport report = run.await();
            assertEquals(STEPS, report.steps());
            RobotSummary r1 = report.robots().get(0);
            assertEquals(0, r1.collisions(), "never touches a wall");
            assertTrue(r1.distance() > 8000, "goes round, not in circles on the spot: " + r1.distance());
            List<Snapshot> snapshots;
            synchronized (run.snapshots) {
                snapshots = List.copyOf(run.snapshots);
            }
            double farthest = 0;
            int corners = 0;
            boolean nearX = false;
            for (Snapshot s : snapshots) {
                if (s.step() < 100) {
                    continue; // driving to the first wall and turning along it
                }
                Snapshot.RobotView v = s.robots().get(0);
                double nearest = Math.min(Math.min(v.x(), ROOM - v.x()), Math.min(v.y(), ROOM - v.y()));
                farthest = Math.max(farthest, nearest);
                boolean nowNearX = Math.min(v.x(), ROOM - v.x()) < Math.min(v.y(), ROOM - v.y());
                if (nowNearX != nearX) {
                    corners++;
                    nearX = nowNearX;
                }
            }
            assertTrue(farthest < 1000, "keeps within 1 m of a wall once following: " + farthest);
            assertTrue(corners >= 3, "follows the walls round the corners: " + corners);
        }
    }
}
