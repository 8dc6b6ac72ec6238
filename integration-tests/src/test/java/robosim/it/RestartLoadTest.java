package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.ControlReply;
import robosim.protocol.Message;
import robosim.protocol.RobotParameters;
import robosim.protocol.Snapshot;
import robosim.protocol.Bye;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldDescription;
import robosim.protocol.recording.RecordingReader;
import robosim.protocol.recording.RecordingWriter;

/**
 * A control client's {@code restart} and {@code load} on a live Environment: the robots of the run
 * are told and disconnected, a viewer stays and is sent the new world, the recording goes on into
 * it, the same robots at the same steps give the same run again, and a load that cannot be carried
 * out leaves the run as it was. The worlds are copies of {@code empty-room.xml} in a folder of the test.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class RestartLoadTest {
    private final ExecutorService threads = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "scripted-robot");
        t.setDaemon(true);
        return t;
    });
    @TempDir
    Path dir;
    private World room;
    private RobotParameters p3dx;

    @BeforeEach
    void worlds() throws Exception {
        String params = LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p").toAbsolutePath().toString();
        Files.writeString(dir.resolve("room.xml"), Files.readString(LocalEnvironment.root()
                .resolve("testLoadFiles/environment/empty-room.xml")).replace("../robots/p3dx.p", params));
        Files.writeString(dir.resolve("solo.xml"), """
                <world name="solo" width="4000" height="4000" boundary="true">
                  <robot name="s1" type="pioneer" x="2000" y="2000" th="0" params="%s"/>
                </world>
                """.formatted(params));
        Files.writeString(dir.resolve("broken.xml"), """
                <world name="broken" width="4000" height="4000">
                  <robot name="s1" type="pioneer" x="2000" params="%s"/>
                </world>
                """.formatted(params));
        room = WorldReader.read(dir.resolve("room.xml"));
        p3dx = room.robots().get(0).parameters();
    }

    @AfterEach
    void stopRobots() {
        threads.shutdownNow();
    }

    private List<Future<String>> start(LocalEnvironment h, String... names) {
        List<Future<String>> byes = new ArrayList<>();
        for (String name : names) {
            byes.add(threads.submit(new ScriptedRobot(h.robotPort(), name, p3dx, true)));
        }
        return byes;
    }

    private static void confirmed(String text, ControlReply reply) {
        assertTrue(reply.ok(), "refused: " + reply.text());
        assertEquals(text, reply.text());
    }

    /** @return the next world a viewer is sent, passing over snapshots; bounded by the peer's read timeout */
    private static WorldDescription nextWorld(RawPeer viewer) throws Exception {
        for (int i = 0; i < 10_000; i++) {
            Message m = viewer.read();
            if (m instanceof WorldDescription w) {
                return w;
            }
        }
        throw new AssertionError("no world among 10000 messages");
    }

    @Test
    void aRestartRunsTheSameWorldAgainAndTheSameRobotsGiveTheSameRun() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment(room, 1, ServerOptions.loopback());
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl");
             RawPeer viewer = new RawPeer(h.viewerPort())) {
            viewer.send(new ViewerHello("watcher"));
            assertEquals("empty-room", nextWorld(viewer).name());
            control.send("pause");
            List<Future<String>> first = start(h, "r1", "r2");
            confirmed("paused after step 0", control.reply());
            confirmed("ran 25 steps; paused after step 25", control.ask("step", "25"));
            List<RobotSummary> before = List.of(h.sim.summary("r1"), h.sim.summary("r2"));
            assertTrue(before.get(0).distance() > 100, "they drove: " + before);

            confirmed("restart by control client ctl after step 25: world empty-room (seed 1) waits for its robots",
                    control.ask("restart"));

            for (Future<String> bye : first) {
                // the run they were in ended: they were not dropped from it
                assertEquals(Bye.DONE + "the run ended for a restart by control client ctl after step 25; connect"
                        + " again to join the new run", bye.get(30, TimeUnit.SECONDS));
            }
            assertEquals("empty-room", nextWorld(viewer).name());
            start(h, "r1", "r2");
            confirmed("ran 25 steps; paused after step 25", control.ask("step", "25"));
            confirmed("stopped after step 25", control.ask("stop"));
            RunReport report = h.await();
            assertEquals(before, report.robots(), "the same run again, pose for pose");
            assertTrue(report.departures().isEmpty(), "the new run lost no robot: " + report.departures());
            assertEquals(List.of(), report.absent(), "both came to the new run");
        }
    }

    @Test
    void aRunStoppedAfterARestartBeforeItsRobotsCameReportsThemAbsent() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment(room, 1, ServerOptions.loopback());
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            control.send("pause");
            List<Future<String>> first = start(h, "r1", "r2");
            confirmed("paused after step 0", control.reply());
            confirmed("ran 2 steps; paused after step 2", control.ask("step", "2"));
            confirmed("restart by control client ctl after step 2: world empty-room (seed 1) waits for its robots",
                    control.ask("restart"));
            for (Future<String> bye : first) {
                bye.get(30, TimeUnit.SECONDS);
            }

            confirmed("stopped after step 0", control.ask("stop"));
            RunReport report = h.await();
            assertEquals(List.of("r1", "r2"), report.absent());
            assertTrue(report.departures().isEmpty(), report.departures().toString());
        }
    }

    @Test
    void aLoadRunsTheNewWorldForItsRobotsAndTheRecordingGoesOnIntoIt() throws Exception {
        Path recording = dir.resolve("run.rsr");
        try (LocalEnvironment h = new LocalEnvironment(room, 1, ServerOptions.loopback(),
                RecordingWriter.create(recording, false));
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl");
             RawPeer viewer = new RawPeer(h.viewerPort())) {
            viewer.send(new ViewerHello("watcher"));
            nextWorld(viewer);
            control.send("pause");
            List<Future<String>> first = start(h, "r1", "r2");
            confirmed("paused after step 0", control.reply());
            confirmed("ran 5 steps; paused after step 5", control.ask("step", "5"));

            confirmed("load of world solo by control client ctl after step 5: world solo (seed 1) waits for its robots",
                    control.ask("load", "solo.xml"));

            assertTrue(first.get(0).get(30, TimeUnit.SECONDS).startsWith(Bye.DONE + "the run ended for a load of world solo"));
            WorldDescription loaded = nextWorld(viewer);
            assertEquals(List.of("s1"), loaded.robots().stream().map(WorldDescription.RobotInfo::name).toList());
            start(h, "s1");
            confirmed("ran 3 steps; paused after step 3", control.ask("step", "3"));
            confirmed("stopped after step 3", control.ask("stop"));
            RunReport report = h.await();
            assertEquals(3, report.steps());
            assertEquals(List.of("s1"), report.robots().stream().map(RobotSummary::name).toList());
        }
        try (RecordingReader reader = RecordingReader.open(recording)) {
            List<String> seen = new ArrayList<>();
            Snapshot s;
            while ((s = reader.next()) != null) {
                seen.add(reader.world().name() + "@" + s.step());
            }
            assertEquals(List.of("empty-room@0", "empty-room@1", "empty-room@2", "empty-room@3", "empty-room@4",
                    "empty-room@5", "solo@0", "solo@1", "solo@2", "solo@3"), seen);
        }
    }

    @Test
    void aLoadThatCannotBeCarriedOutIsRefusedAndTheRunGoesOnUnharmed() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment(room, 1, ServerOptions.loopback());
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            control.send("pause");
            List<Future<String>> robots = start(h, "r1", "r2");
            confirmed("paused after step 0", control.reply());
            confirmed("ran 2 steps; paused after step 2", control.ask("step", "2"));

            ControlReply broken = control.ask("load", "broken.xml");
            ControlReply outside = control.ask("load", "../elsewhere.xml");
            ControlReply missing = control.ask("load", "nothing.xml");

            assertFalse(broken.ok());
            assertTrue(broken.text().startsWith("load: ") && broken.text().contains("broken.xml:2: ")
                    && broken.text().contains("missing required attribute y"), broken.text());
            assertFalse(outside.ok());
            assertTrue(outside.text().startsWith("load: ../elsewhere.xml is outside "), outside.text());
            assertFalse(missing.ok());
            assertEquals("load: no world file nothing.xml in " + dir.toAbsolutePath().normalize(), missing.text());
            confirmed("ran 2 steps; paused after step 4", control.ask("step", "2"));
            confirmed("stopped after step 4", control.ask("stop"));
            RunReport report = h.await();
            assertEquals(4, report.steps());
            assertTrue(report.departures().isEmpty(), report.departures().toString());
            for (Future<String> bye : robots) {
                assertEquals("done: stopped by control client ctl", bye.get(30, TimeUnit.SECONDS));
            }
        }
    }
}
