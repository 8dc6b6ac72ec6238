package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import picocli.CommandLine;
import robosim.cli.Main;
import robosim.env.core.RobotSummary;
import robosim.env.net.Departure;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.protocol.Await;
import robosim.protocol.CapturedLog;
import robosim.protocol.Bye;
import robosim.protocol.ControlReply;

/**
 * Run control on a live Environment in world {@code empty-room.xml} (robots r1 and r2), its robots
 * scripted programs on raw sockets and its control clients on raw sockets or {@code robosim control}.
 * Each test sends its first pause before the robots connect, so the run pauses before step 1.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class RunControlTest {
    private final ExecutorService threads = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "scripted-robot");
        t.setDaemon(true);
        return t;
    });
    private final List<ScriptedRobot> robots = new ArrayList<>();

    @AfterEach
    void stopRobots() {
        threads.shutdownNow();
    }

    /** Starts a scripted program for each of the world's robots. */
    private List<Future<String>> start(LocalEnvironment h, boolean moving) {
        List<Future<String>> byes = new ArrayList<>();
        for (String name : h.sim.robotNames()) {
            ScriptedRobot r = new ScriptedRobot(h.robotPort(), name, h.sim.world().robots().get(0).parameters(), moving);
            robots.add(r);
            byes.add(threads.submit(r));
        }
        return byes;
    }

    private static void confirmed(String text, ControlReply reply) {
        assertTrue(reply.ok(), "refused: " + reply.text());
        assertEquals(text, reply.text());
    }

    private static ControlReply askUnchecked(ControlPeer control, String op, String... args) {
        try {
            return control.ask(op, args);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static void refused(String reason, ControlReply reply) {
        assertFalse(reply.ok(), "confirmed: " + reply.text());
        assertTrue(reply.text().contains(reason), reply.text());
    }

    @Test
    void pauseStepAndResumeGiveTheSameTrajectoryAsAnUninterruptedRun() throws Exception {
        List<RobotSummary> uninterrupted;
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback().withMaxSteps(60))) {
            start(h, true);
            uninterrupted = h.await().robots();
        }
        assertTrue(uninterrupted.get(0).distance() > 100, "the robots drive: " + uninterrupted);
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback().withMaxSteps(60));
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            control.send("pause");
            start(h, true);
            confirmed("paused after step 0", control.reply());
            confirmed("ran 7 steps; paused after step 7", control.ask("step", "7"));
            ScriptedRobot last = robots.get(robots.size() - 1);
            Await.until("a keep-alive while paused (one after each silent second)", () -> last.keepAlives.get() >= 1);
            confirmed("already paused at step 7", control.ask("pause"));
            confirmed("ran 1 step; paused after step 8", control.ask("step", "1"));
            confirmed("resumed after step 8", control.ask("resume"));
            RunReport report = h.await();

            assertEquals("step limit 60 reached", report.endReason());
            assertEquals(uninterrupted, report.robots(), "the same trajectories, pose for pose");
            assertTrue(last.keepAlives.get() >= 1, "kept alive while paused");
            assertTrue(report.departures().isEmpty(), "no robot was lost while paused: " + report.departures());
        }
    }

    @Test
    void eachRequestIsConfirmedOrRefusedWithItsReasonAndARefusalLeavesTheRunAsItWas() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            control.send("pause");
            List<Future<String>> byes = start(h, false);
            confirmed("paused after step 0", control.reply());
            confirmed("resumed after step 0", control.ask("resume"));
            refused("step N runs steps while the run is paused", control.ask("step", "3"));
            ControlReply paused = control.ask("pause");
            assertTrue(paused.ok() && paused.text().matches("paused after step \\d+"), paused.text());
            long k = Long.parseLong(paused.text().substring("paused after step ".length()));

            refused("N is a whole number from 1 to 1000000, got '0'", control.ask("step", "0"));
            refused("a factor of real time from 0.01 to 1000, got '0'", control.ask("pace", "0"));
            refused("no robot named 'r9'", control.ask("move", "r9", "3000", "3000", "0"));
            refused("no robot named 'r9'", control.ask("remove", "r9"));
            refused("within 100000000 of the origin", control.ask("move", "r1", "2e8", "0", "0"));
            refused("its body would overlap something there", control.ask("move", "r1", "4500", "4500", "0"));
            refused("load: ../robots/p3dx.p is outside", control.ask("load", "../robots/p3dx.p"));
            refused("unknown operation 'jump'", control.ask("jump"));
            confirmed("ran 2 steps; paused after step " + (k + 2), control.ask("step", "2"));

            confirmed("pace 2.0 x real time from step " + (k + 3), control.ask("pace", "2"));
            confirmed("pace max (as fast as possible) from step " + (k + 3), control.ask("pace", "max"));
            confirmed("robot r1 moved to (3000, 1500, 90) after step " + (k + 2),
                    control.ask("move", "r1", "3000", "1500", "90"));
            confirmed("robot r2 removed after step " + (k + 2) + "; it stays where it stopped",
                    control.ask("remove", "r2"));
            refused("robot r2 is not in the run", control.ask("remove", "r2"));
            confirmed("stopped after step " + (k + 2), control.ask("stop"));
            RunReport report = h.await();

            assertEquals("stopped by control client ctl", report.endReason());
            assertEquals(k + 2, report.steps());
            RobotSummary r1 = report.robots().get(0);
            assertEquals(List.of(3000.0, 1500.0, 90.0), List.of(r1.x(), r1.y(), r1.th()), "placed");
            assertEquals(List.of(1500.0, 1500.0, 45.0), List.of(r1.odoX(), r1.odoY(), r1.odoTh()),
                    "its odometry unchanged");
            assertEquals("removed by control client ctl after step " + (k + 2), byes.get(1).get(30, TimeUnit.SECONDS));
            assertEquals(Departure.Kind.DROPPED, report.departure("r2").orElseThrow().kind());
            assertEquals("done: stopped by control client ctl", byes.get(0).get(30, TimeUnit.SECONDS));
        }
    }

    @Test
    void aPaceHoldsEachStepToItsShareOfRealTime() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             ControlPeer control = new ControlPeer(h.viewerPort(), "ctl")) {
            control.send("pause");
            start(h, true);
            confirmed("paused after step 0", control.reply());
            // 100 ms steps at 5 x real time: a step each 20 ms, the first at once
            confirmed("pace 5.0 x real time from step 1", control.ask("pace", "5"));
            long started = System.nanoTime();
            confirmed("ran 10 steps; paused after step 10", control.ask("step", "10"));
            long ms = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
            confirmed("stopped after step 10", control.ask("stop"));

            assertTrue(ms >= 180, "10 steps took " + ms + " ms");
            assertEquals(10, h.await().steps());
        }
    }

    @Test
    void twoControlClientsAtOnceAreEachAnsweredInTurn() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             ControlPeer a = new ControlPeer(h.viewerPort(), "a");
             ControlPeer b = new ControlPeer(h.viewerPort(), "b")) {
            a.send("pause");
            start(h, true);
            confirmed("paused after step 0", a.reply());
            confirmed("already paused at step 0", b.ask("pause"));
            confirmed("ran 3 steps; paused after step 3", b.ask("step", "3"));
            confirmed("ran 2 steps; paused after step 5", a.ask("step", "2"));
            // at real time the 4 steps take 300 ms: the second request comes while the first runs
            confirmed("pace realtime from step 6", a.ask("pace", "realtime"));

            a.send("step", "4");
            b.send("step", "4");
            ControlReply fromA = a.reply();
            ControlReply fromB = b.reply();
            assertTrue(fromA.ok() != fromB.ok(), "one runs its steps, the other is told one is under way: "
                    + fromA + ", " + fromB);
            ControlReply refusal = fromA.ok() ? fromB : fromA;
            assertTrue(refusal.text().startsWith("a step N is under way"), refusal.text());
            confirmed("ran 4 steps; paused after step 9", fromA.ok() ? fromA : fromB);
            confirmed("stopped after step 9", b.ask("stop"));

            assertEquals("stopped by control client b", h.await().endReason());
            assertEquals("done: stopped by control client b", assertInstanceOf(Bye.class, a.peer.read()).reason());
        }
    }

    @Test
    void aControlClientThatDisconnectsMidRequestLeavesTheRunUnharmed() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             ControlPeer b = new ControlPeer(h.viewerPort(), "b")) {
            List<Future<String>> byes;
            try (ControlPeer a = new ControlPeer(h.viewerPort(), "a")) {
                a.send("pause");
                byes = start(h, true);
                confirmed("paused after step 0", a.reply());
                a.send("step", "3");
                // the pause's answer says the step 3 sent before it has been taken (at this or an earlier boundary)
                ControlReply pause = a.ask("pause");
                assertTrue(pause.ok() && pause.text().matches("already paused at step [0-3]"), pause.text());
                // half a frame: its length says 100 bytes, 10 come, and the client is gone
                a.peer.sendRaw(new byte[] {0, 0, 0, 100, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
            }
            // refused while a's step 3 is under way: asked again until it is taken
            ControlReply stepped = Await.value(Await.PATIENCE, "the step taken once a's steps are run", () -> {
                ControlReply r = askUnchecked(b, "step", "1");
                assertTrue(r.ok() || r.text().startsWith("a step N is under way"), r.text());
                return r.ok() ? r : null;
            });
            confirmed("ran 1 step; paused after step 4", stepped);
            confirmed("stopped after step 4", b.ask("stop"));
            RunReport report = h.await();

            assertEquals("stopped by control client b", report.endReason());
            assertEquals(4, report.steps());
            assertTrue(report.departures().isEmpty(), report.departures().toString());
            for (Future<String> bye : byes) {
                assertEquals("done: stopped by control client b", bye.get(30, TimeUnit.SECONDS));
            }
        }
    }

    @Test
    void theControlCommandPrintsTheAnswerAndExitsOneOnARefusal() throws Exception {
        try (LocalEnvironment h = new LocalEnvironment("empty-room.xml", ServerOptions.loopback());
             CapturedLog log = new CapturedLog("robosim.env.net")) {
            String port = Integer.toString(h.viewerPort());
            Future<Integer> pause = threads.submit(() -> control(new StringWriter(), new StringWriter(),
                    "control", "--viewer-port", port, "pause"));
            // the pause is taken once the run starts: it waits for its robots
            Await.until("robosim control attached before the run", () -> log.lines().stream()
                    .anyMatch(l -> l.startsWith("control client ") && l.endsWith(" attached at step 0")));
            start(h, false);
            assertEquals(0, pause.get(30, TimeUnit.SECONDS));

            StringWriter out = new StringWriter();
            StringWriter err = new StringWriter();
            assertEquals(1, control(out, err, "control", "--viewer-port", port, "step", "0"));
            assertEquals("robosim control: refused: step N: N is a whole number from 1 to 1000000, got '0'",
                    err.toString().strip());

            err = new StringWriter();
            assertEquals(1, control(out, err, "control", "--viewer-port", port, "move", "r1", "-1", "-1", "0"));
            assertTrue(err.toString().contains("its body would overlap something there"), err.toString());

            err = new StringWriter();
            assertEquals(1, control(out, err, "control", "--viewer-port", port, "load", "../robots/p3dx.p"));
            assertTrue(err.toString().strip().startsWith("robosim control: refused: load: ../robots/p3dx.p is outside "),
                    err.toString());

            out = new StringWriter();
            assertEquals(0, control(out, new StringWriter(), "control", "--viewer-port", port, "step", "2"));
            assertTrue(out.toString().strip().matches("ran 2 steps; paused after step \\d+"), out.toString());
            out = new StringWriter();
            assertEquals(0, control(out, new StringWriter(), "control", "--viewer-port", port, "stop"));
            assertTrue(out.toString().strip().matches("stopped after step \\d+"), out.toString());
            assertEquals("stopped by control client control", h.await().endReason());
        }
    }

    private static int control(StringWriter out, StringWriter err, String... args) {
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        return cl.execute(args);
    }
}
