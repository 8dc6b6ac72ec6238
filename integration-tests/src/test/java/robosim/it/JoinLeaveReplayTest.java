package robosim.it;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.cli.Background;
import robosim.env.net.Join;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.FrameReader;
import robosim.protocol.RobotParameters;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.RecordingReader;
import robosim.protocol.recording.RecordingWriter;
import robosim.protocol.recording.SnapshotListener;
import robosim.viewer.draw.PngImageWriter;
import robosim.viewer.draw.RenderedImages;
import robosim.viewer.draw.SnapshotPainter;
import robosim.viewer.draw.WorldRenderer;
import robosim.viewer.replay.RecordingSummary;
import robosim.viewer.replay.Replay;
import robosim.viewer.replay.ReplayRange;

/**
 * Robots that join and leave a run under way, recorded and replayed. An open world split in two by
 * a wall: r1 drives on the left from the start; on the right r2 (named by the world) joins late and
 * leaves, and a robot the world does not name joins at the spawn pose. r1 cannot sense them and no
 * message passes, so its run is the run it has alone; every join and leave is in the recording, and
 * the replay draws every step with the newcomer in its world.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class JoinLeaveReplayTest {
    private static final int STEPS = 60;

    @TempDir
    Path dir;

    private World world() throws IOException {
        Path robots = LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p").toAbsolutePath();
        Path file = dir.resolve("halves.xml");
        Files.writeString(file, """
                <world name="halves" width="10000" height="6000" boundary="true" open="true">
                  <wall x1="5000" y1="0" x2="5000" y2="6000" thickness="200" height="500"/>
                  <robot name="r1" type="pioneer" x="1500" y="3000" th="0" params="%1$s"/>
                  <robot name="r2" type="pioneer" x="7000" y="1500" th="90" params="%1$s"/>
                  <spawn x="8500" y="4500" th="180"/>
                  <end when="steps" steps="%2$d"/>
                </world>
                """.formatted(robots, STEPS));
        return WorldReader.read(file);
    }

    /** Paced at real time, so that robots started on the way join while the run goes on. */
    private static ServerOptions realtime() {
        return new ServerOptions("127.0.0.1", 0, 0, 0, true, 10_000, 60_000, 0, FrameReader.DEFAULT_MAX_FRAME);
    }

    /**
     * Runs the world with r1 driving, recording every step; at step 10 starts r2 (it leaves after 15
     * steps) and at step 20 the newcomer, when {@code visitors}.
     */
    private RunReport run(Path recording, boolean visitors) throws Exception {
        World w = world();
        RobotParameters p = w.robots().get(0).parameters();
        List<CompletableFuture<String>> started = new ArrayList<>();
        int[] port = new int[1];
        SnapshotListener starter = new SnapshotListener() {
            @Override
            public void world(WorldDescription world) {
            }

            @Override
            public void snapshot(Snapshot s) {
                if (visitors && s.step() == 10) {
                    started.add(Background.supply("r2", () -> call(new Visitor(port[0], "r2", p, 15))));
                } else if (visitors && s.step() == 20) {
                    started.add(Background.supply("visitor", () -> call(new Visitor(port[0], "visitor", p, 0))));
                }
            }
        };
        try (LocalEnvironment env = new LocalEnvironment(w, 1, realtime(), RecordingWriter.create(recording, true),
                starter)) {
            port[0] = env.robotPort();
            CompletableFuture<String> r1 = Background.supply("r1",
                    () -> call(new ScriptedRobot(env.robotPort(), "r1", p, true)));
            RunReport report = env.await(120);
            r1.get(30, TimeUnit.SECONDS);
            for (CompletableFuture<String> f : started) {
                f.get(30, TimeUnit.SECONDS);
            }
            return report;
        }
    }

    private static String call(java.util.concurrent.Callable<String> robot) {
        try {
            return robot.call();
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    private static List<Snapshot> snapshots(Path recording) throws IOException {
        List<Snapshot> all = new ArrayList<>();
        try (RecordingReader reader = RecordingReader.open(recording)) {
            Snapshot s;
            while ((s = reader.next()) != null) {
                all.add(s);
            }
        }
        return all;
    }

    private static Snapshot.RobotView view(Snapshot s, String robot) {
        return s.robots().stream().filter(r -> r.name().equals(robot)).findFirst().orElse(null);
    }

    @Test
    void joinsAndLeavesAreRecordedAndReplayedAndLeaveTheOtherRobotsRunAsItWas() throws Exception {
        Path alone = dir.resolve("alone.rsr");
        Path visited = dir.resolve("visited.rsr");
        run(alone, false);
        RunReport report = run(visited, true);

        assertEquals(List.of(Join.Kind.LATE, Join.Kind.SPAWNED), report.joins().stream().map(Join::kind).toList());
        assertEquals("r2", report.departures().get(0).robot());
        List<Snapshot> a = snapshots(alone);
        List<Snapshot> b = snapshots(visited);
        assertEquals(STEPS + 1, a.size());
        assertEquals(STEPS + 1, b.size());
        for (int k = 0; k <= STEPS; k++) {
            Snapshot.RobotView x = view(a.get(k), "r1");
            Snapshot.RobotView y = view(b.get(k), "r1");
            assertEquals(List.of(x.x(), x.y(), x.th(), x.odoX(), x.odoY()), List.of(y.x(), y.y(), y.th(), y.odoX(),
                    y.odoY()), "r1 after step " + k);
            assertArrayEquals(x.sonar(), y.sonar(), "r1's sonar after step " + k);
        }
        assertTrue(view(a.get(STEPS), "r1").x() > 1700, "r1 drove: " + view(a.get(STEPS), "r1"));
        List<String> events = b.stream().flatMap(s -> s.events().stream())
                .map(e -> e.robot() + " " + e.what() + (e.reason().isEmpty() ? "" : ": " + e.reason())).toList();
        assertEquals(List.of("r2 joined late", "r2 left: done visiting", "visitor spawned"),
                events.stream().sorted().toList());
        Snapshot last = b.get(STEPS);
        assertFalse(view(last, "r2").connected(), "r2 left");
        assertTrue(view(last, "visitor").connected(), "the newcomer stayed");
        assertEquals(List.of(8500.0, 4500.0), List.of(view(last, "visitor").x(), view(last, "visitor").y()));

        try (RecordingReader reader = RecordingReader.open(visited)) {
            RenderedImages out = new RenderedImages(SnapshotPainter.flat(new WorldRenderer(), RecordedRun.RENDER),
                    new PngImageWriter(dir.resolve("replay")), 1, false);
            Replay.Result replayed = Replay.run(reader, out, ReplayRange.ALL);
            assertEquals(STEPS + 1, replayed.imagesDrawn());
            assertEquals(List.of("r1", "r2", "visitor"), reader.world().robots().stream()
                    .map(WorldDescription.RobotInfo::name).toList());
        }
        try (RecordingReader reader = RecordingReader.open(visited)) {
            RecordingSummary summary = RecordingSummary.of(reader);
            assertEquals(3, summary.events().size());
            assertEquals(List.of("pioneer", "pioneer", "pioneer"), summary.robots().stream()
                    .map(RecordingSummary.RobotTotals::type).toList());
        }
    }
}
