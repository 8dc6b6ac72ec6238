package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import picocli.CommandLine;
import robosim.cli.Main;
import robosim.env.net.ServerOptions;
import robosim.protocol.ControlReply;
import robosim.protocol.ControlRequest;
import robosim.protocol.LogLine;
import robosim.protocol.Message;
import robosim.protocol.RunStatus;

/**
 * The control requests that change nothing, {@code status} and {@code log}, on a live Environment in
 * world {@code empty-room.xml} (robots r1 and r2).
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class RunStatusTest {
    private final ExecutorService threads = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "scripted-robot");
        t.setDaemon(true);
        return t;
    });

    @AfterEach
    void stopRobots() {
        threads.shutdownNow();
    }

    private static RunStatus status(ControlPeer control, long id) throws Exception {
        control.peer.send(new ControlRequest(id, "status", List.of()));
        Message m = control.peer.read();
        RunStatus s = assertInstanceOf(RunStatus.class, m);
        assertEquals(id, s.id());
        return s;
    }

    @Test
    void statusShowsEachRobotsTypeDriverPoseAndTheLastStepItAnswered() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            control.send("pause");
            threads.submit(new ScriptedRobot(h.robotPort(), "r1", h.sim.world().robots().get(0).parameters(), false));
            threads.submit(new ScriptedRobot(h.robotPort(), "r2", h.sim.world().robots().get(1).parameters(), false));
            assertEquals("paused after step 0", control.reply().text());
            assertEquals("ran 3 steps; paused after step 3", control.ask("step", "3").text());

            RunStatus s = status(control, 100);

            assertEquals("empty-room", s.world());
            assertEquals(3, s.step());
            assertEquals(300, s.timeMs());
            assertTrue(s.paused());
            assertEquals(0, s.pace());
            RunStatus.RobotStatus r1 = s.robots().get(0);
            assertEquals(List.of("r1", "pioneer"), List.of(r1.name(), r1.type()));
            assertTrue(r1.connected());
            assertTrue(r1.drivenBy().startsWith("program at 127.0.0.1:"), r1.drivenBy());
            assertEquals(List.of(1500.0, 1500.0, 45.0), List.of(r1.x(), r1.y(), r1.th()));
            assertEquals(3, r1.lastStep());
            assertEquals(List.of(0L, 0L, 0L), List.of(r1.collisions(), r1.sent(), r1.received()));
        }
    }

    @Test
    void aRemovedRobotIsShownDisconnectedWithNothingDrivingIt() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            control.send("pause");
            threads.submit(new ScriptedRobot(h.robotPort(), "r1", h.sim.world().robots().get(0).parameters(), false));
            threads.submit(new ScriptedRobot(h.robotPort(), "r2", h.sim.world().robots().get(1).parameters(), false));
            assertEquals("paused after step 0", control.reply().text());
            assertTrue(control.ask("remove", "r2").ok());

            RunStatus.RobotStatus r2 = status(control, 100).robots().get(1);

            assertFalse(r2.connected());
            assertEquals("", r2.drivenBy());
        }
    }

    @Test
    void aRealTimeRunSaysItsPaceBeforeItsFirstRobotJoins() throws Exception {
        ServerOptions realtime = new ServerOptions("127.0.0.1", 0, 0, 0, true, 10_000, 60_000, 0, 4 << 20);
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", realtime)) {
            StringWriter out = new StringWriter();
            CommandLine cl = Main.commandLine();
            cl.setOut(new PrintWriter(out, true));
            cl.setErr(new PrintWriter(new StringWriter(), true));

            assertEquals(0, cl.execute("control", "--viewer-port", Integer.toString(h.viewerPort()), "status"));

            String line = out.toString().lines().findFirst().orElseThrow();
            assertTrue(line.contains(" - pace real time - "), line);
            assertTrue(line.endsWith("0 of 2 robots connected"), line);
        }
    }

    @Test
    void theControlCommandPrintsTheRunLineAndATableOfTheRobots() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            control.send("pause");
            threads.submit(new ScriptedRobot(h.robotPort(), "r1", h.sim.world().robots().get(0).parameters(), false));
            threads.submit(new ScriptedRobot(h.robotPort(), "r2", h.sim.world().robots().get(1).parameters(), false));
            assertEquals("paused after step 0", control.reply().text());
            StringWriter out = new StringWriter();
            CommandLine cl = Main.commandLine();
            cl.setOut(new PrintWriter(out, true));
            cl.setErr(new PrintWriter(new StringWriter(), true));

            assertEquals(0, cl.execute("control", "--viewer-port", Integer.toString(h.viewerPort()), "status"));

            List<String> lines = out.toString().lines().toList();
            assertEquals("world empty-room - step 0 (0.0 s) - paused - pace max - 2 of 2 robots connected", lines.get(0));
            assertTrue(lines.get(1).startsWith("Name\tType\tDriven by\t"), lines.get(1));
            assertTrue(lines.get(2).matches("r1\tpioneer\tprogram at 127\\.0\\.0\\.1:\\d+\t1500, 1500, 45\t0, 0\\.0\tno"
                    + "\t0\t0\t0\t0\tconnected"), lines.get(2));
            assertEquals(4, lines.size());
        }
    }

    @Test
    void aStatusWithArgumentsIsRefusedWithTheRule() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            ControlReply r = control.ask("status", "r1");

            assertFalse(r.ok());
            assertEquals("status takes 0 arguments (status), got 1", r.text());
        }
    }

    @Test
    void aFollowerIsSentTheLinesOfRobotsJoiningAndOfRequestsCarriedOut() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             ControlPeer follower = new ControlPeer(h.viewerPort(), "panel");
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            ControlReply answer = follower.ask("log");
            assertTrue(answer.ok(), answer.text());
            assertEquals("following the Environment's log from step 0", answer.text());
            control.send("pause");
            threads.submit(new ScriptedRobot(h.robotPort(), "r1", h.sim.world().robots().get(0).parameters(), false));
            threads.submit(new ScriptedRobot(h.robotPort(), "r2", h.sim.world().robots().get(1).parameters(), false));
            assertEquals("paused after step 0", control.reply().text());
            control.ask("remove", "r2");

            List<String> lines = new ArrayList<>();
            while (lines.stream().noneMatch(l -> l.contains("removed robot r2"))) {
                Message m = follower.peer.read();
                if (m instanceof LogLine l) {
                    lines.add(l.level() + " " + l.text());
                }
            }

            assertTrue(lines.stream().anyMatch(l -> l.startsWith("INFO ") && l.contains("robot r1 connected")), lines::toString);
            assertTrue(lines.stream().anyMatch(l -> l.contains("control client ctl removed robot r2 after step 0")),
                    lines::toString);
        }
    }

    @Test
    void aClientThatDoesNotAskIsSentNoLogLines() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            control.send("pause");
            threads.submit(new ScriptedRobot(h.robotPort(), "r1", h.sim.world().robots().get(0).parameters(), false));
            threads.submit(new ScriptedRobot(h.robotPort(), "r2", h.sim.world().robots().get(1).parameters(), false));

            // reply() fails on any message but an answer, a log line among them
            assertEquals("paused after step 0", control.reply().text());
            assertEquals("ran 2 steps; paused after step 2", control.ask("step", "2").text());
            assertFalse(control.ask("log", "now").ok());
        }
    }
}
