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
import robosim.examples.colorfollower.ColorFollower;
import robosim.protocol.Snapshot;

/**
 * ARIA's colour-following example ({@code examples/color-follower}) sees a red box 15° to its
 * right, turns toward it and drives up to it, stopping short of it.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class ColorFollowerExampleTest {
    private static final int STEPS = 300;
    /** The red box's near face, x mm, and its centre's y. */
    private static final double FACE = 4500;
    private static final double BOX_Y = 3000;

    @TempDir
    Path dir;

    @Test
    void itTurnsTowardTheRedBoxAndApproachesIt() throws Exception {
        Path world = ThreadedRun.world(dir, "red.xml", """
                <?xml version="1.0" encoding="UTF-8"?>
                <world name="red" width="8000" height="6000" stepMs="100" boundary="true">
                  <polygon points="4500,2800 4900,2800 4900,3200 4500,3200" height="500" color="red"/>
                  <polygon points="1500,5000 2500,5000 2500,5400 1500,5400" height="500" color="blue"/>
                  <robot name="r1" type="pioneer" x="1500" y="3800" th="0" params="%ROBOTS%/p3dx.p"/>
                </world>
                """);
        double startBearing = Math.toDegrees(Math.atan2(BOX_Y - 3800, FACE - 1500));
        assertTrue(startBearing < -14 && startBearing > -16, "the box starts about 15° right: " + startBearing);
        try (ThreadedRun run = new ThreadedRun(world, 1, STEPS)) {
            run.robot(() -> {
                ColorFollower follower = new ColorFollower(new ArRobot("r1", "127.0.0.1", run.port(), "p3dx"), 1);
                follower.connect();
                follower.run();
                return null;
            });
            RunReport report = run.await();
            assertEquals(STEPS, report.steps());
            RobotSummary r1 = report.robots().get(0);
            assertEquals(0, r1.collisions(), "stops before the box");
            List<Snapshot> snapshots;
            synchronized (run.snapshots) {
                snapshots = List.copyOf(run.snapshots);
            }
            Snapshot.RobotView end = snapshots.get(snapshots.size() - 1).robots().get(0);
            double bearing = Math.toDegrees(Math.atan2(BOX_Y - end.y(), FACE + 200 - end.x())) - end.th();
            assertTrue(Math.abs(bearing) < 6, "faces the box at the end: bearing " + bearing + " from " + end);
            double gap = FACE - end.x();
            assertTrue(gap < 1000 && gap > 0, "has come up to the box: " + gap + " mm short of its face, from "
                    + (FACE - 1500));
            assertTrue(end.th() < -3, "it turned right to face it: heading " + end.th());
        }
    }
}
